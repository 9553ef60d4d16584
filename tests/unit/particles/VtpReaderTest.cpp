#include "particles/VtpReader.hpp"

#include "TestFiles.hpp"
#include "core/Log.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/VtpWriter.hpp"
#include "particles/XmlElement.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace mfdyn;
using mfdyn::test::readFile;
using mfdyn::test::ScratchDir;
using mfdyn::test::writeFile;

namespace {

// Values that stress a binary round trip: the extremes of double, signed zero, subnormals,
// infinities, then random bit patterns over every finite exponent (NaN excluded, since NaN != NaN
// would hide nothing but complicate the check; the comparison is bitwise anyway).
class Values {
public:
    explicit Values(unsigned seed) : rng_(seed) {}
    double next() {
        static const double special[] = {std::numeric_limits<double>::max(),
                                         std::numeric_limits<double>::lowest(),
                                         std::numeric_limits<double>::min(),
                                         std::numeric_limits<double>::denorm_min(),
                                         -std::numeric_limits<double>::denorm_min(),
                                         -0.0,
                                         0.0,
                                         std::numeric_limits<double>::epsilon(),
                                         std::numeric_limits<double>::infinity(),
                                         -std::numeric_limits<double>::infinity(),
                                         1.0 / 3.0};
        if (count_ < std::size(special)) return special[count_++];
        double d;
        do {
            d = std::bit_cast<double>(std::uint64_t(rng_()));
        } while (std::isnan(d));
        return d;
    }
    std::int64_t nextInteger() {
        static const std::int64_t special[] = {std::numeric_limits<std::int64_t>::max(),
                                               std::numeric_limits<std::int64_t>::min(), -1, 0};
        if (intCount_ < std::size(special)) return special[intCount_++];
        return std::int64_t(rng_());
    }

private:
    std::mt19937_64 rng_;
    std::size_t count_ = 0, intCount_ = 0;
};

template <int Dim>
ParticleSet<Dim> makeParticles(std::size_t n, unsigned seed) {
    ParticleSet<Dim> p(n);
    Values v(seed);
    p.scalarField("rho");
    p.vectorField("velocity");
    p.tensorField("F");
    p.symmTensorField("sigma");
    p.integerField("material");
    for (const auto& f : p.fields()) {
        const std::size_t count = f->size() * f->components();
        if (f->isInteger()) {
            auto* data = static_cast<std::int64_t*>(f->data());
            for (std::size_t k = 0; k < count; ++k) data[k] = v.nextInteger();
        } else {
            auto* data = static_cast<double*>(f->data());
            for (std::size_t k = 0; k < count; ++k) data[k] = v.next();
        }
    }
    p.regionNames = {"projectile", "target plate", "a&b <\"c\">"};
    p.materialNames = {"aluminium2024"};
    return p;
}

void expectBitIdentical(const ParticleSetBase& a, const ParticleSetBase& b) {
    ASSERT_EQ(a.dimension(), b.dimension());
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.fieldNames().size(), b.fieldNames().size());
    for (const auto& f : a.fields()) {
        const FieldBase* g = b.findField(f->name());
        ASSERT_NE(g, nullptr) << f->name();
        EXPECT_EQ(g->kind(), f->kind()) << f->name();
        EXPECT_EQ(g->elementType(), f->elementType()) << f->name();
        if (f->size() > 0) {
            EXPECT_EQ(std::memcmp(f->data(), g->data(), f->size() * f->elementBytes()), 0) << f->name();
        }
    }
    EXPECT_EQ(a.regionNames, b.regionNames);
    EXPECT_EQ(a.materialNames, b.materialNames);
}

template <int Dim>
void roundTrip(std::size_t n) {
    ScratchDir dir("roundTrip" + std::to_string(Dim));
    const auto particles = makeParticles<Dim>(n, 42 + Dim);
    const double time = 0.1 + 1e-17;  // not representable in a short decimal
    writeVtp(dir.path() / "p.vtp", particles, time);
    ParticleFile back = readVtp(dir.path() / "p.vtp");
    ASSERT_TRUE(back.hasTime);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back.time), std::bit_cast<std::uint64_t>(time));
    expectBitIdentical(particles, *back.particles);
}

// The VTK header (everything up to the '_' of the appended data) closed as XML, so a
// standard XML checker can judge it; the raw binary after '_' is outside XML by design.
std::string headerAsXml(const std::string& file) {
    const std::size_t marker = file.find("<AppendedData");
    const std::size_t underscore = file.find('_', marker);
    return file.substr(0, underscore) + "\n  </AppendedData>\n</VTKFile>\n";
}

// Locates one appended array of the file and returns its values as doubles.
std::vector<double> fileArray(const std::string& file, const std::string& name) {
    std::size_t stop = 0;
    const XmlElement root = XmlElement::parse(file, "test", "AppendedData", &stop);
    const std::size_t data = file.find('_', stop) + 1;
    std::vector<const XmlElement*> arrays;
    std::vector<const XmlElement*> todo{&root};
    while (!todo.empty()) {
        const XmlElement* e = todo.back();
        todo.pop_back();
        if (e->name == "DataArray" && *e->findAttribute("Name") == name) arrays.push_back(e);
        for (const auto& c : e->children) todo.push_back(&c);
    }
    EXPECT_EQ(arrays.size(), 1u) << name;
    const std::size_t offset = std::stoul(*arrays[0]->findAttribute("offset"));
    std::uint64_t bytes;
    std::memcpy(&bytes, file.data() + data + offset, 8);
    std::vector<double> values(bytes / 8);
    std::memcpy(values.data(), file.data() + data + offset + 8, bytes);
    return values;
}

}  // namespace

TEST(VtpReader, RoundTripIsBitExact1D) {
    roundTrip<1>(257);
}
TEST(VtpReader, RoundTripIsBitExact2D) {
    roundTrip<2>(1000);
}
TEST(VtpReader, RoundTripIsBitExact3D) {
    roundTrip<3>(3001);
}
TEST(VtpReader, RoundTripOfNoParticles) {
    roundTrip<3>(0);
}

TEST(VtpReader, FileLayoutIsWhatParaViewExpects) {
    ScratchDir dir("layout");
    ParticleSet<2> p(1);
    p.position()[0] << 1.5, 2.5;
    p.symmTensorField("sigma")[0].c = {1, 2, 3};  // xx yy xy
    p.tensorField("F")[0] << 1, 2, 3, 4;          // rows (1 2) (3 4)
    p.vectorField("u")[0] << 7, 8;
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    const std::string file = readFile(dir.path() / "p.vtp");
    EXPECT_EQ(file.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                         "byte_order=\"LittleEndian\" header_type=\"UInt64\">",
                         0),
              0u);
    EXPECT_EQ(fileArray(file, "sigma"), (std::vector<double>{1, 2, 0, 3, 0, 0}));  // XX YY ZZ XY YZ XZ
    EXPECT_EQ(fileArray(file, "F"), (std::vector<double>{1, 2, 0, 3, 4, 0, 0, 0, 0}));
    EXPECT_EQ(fileArray(file, "u"), (std::vector<double>{7, 8, 0}));
    EXPECT_EQ(fileArray(file, "position"), (std::vector<double>{1.5, 2.5, 0}));
    EXPECT_NE(file.find("<Verts>"), std::string::npos);
    EXPECT_NE(file.find("NumberOfVerts=\"1\""), std::string::npos);
    // Empty name tables are left out rather than written as zero-tuple string arrays.
    EXPECT_EQ(file.find("regionNames"), std::string::npos);
}

TEST(VtpReader, HeaderIsWellFormedXml) {
    ScratchDir dir("xml");
    auto p = makeParticles<3>(10, 1);
    writeVtp(dir.path() / "p.vtp", p, 1.0);
    const std::string xml = headerAsXml(readFile(dir.path() / "p.vtp"));
    EXPECT_NO_THROW(XmlElement::parse(xml, "header.xml"));
#ifdef MFDYN_XMLLINT
    writeFile(dir.path() / "header.xml", xml);
    const std::string command =
        std::string(MFDYN_XMLLINT) + " --noout " + (dir.path() / "header.xml").string();
    EXPECT_EQ(std::system(command.c_str()), 0) << xml;
#endif
}

TEST(VtpReader, DimensionIsInferredWithoutMfdynDimension) {
    ScratchDir dir("infer");
    for (int dim = 1; dim <= 3; ++dim) {
        withDimension(dim, [&](auto d) {
            constexpr int Dim = decltype(d)::value;
            ParticleSet<Dim> p(3);
            for (auto& x : p.position()) x.setConstant(0.5);
            writeVtp(dir.path() / "p.vtp", p, 0.0);
        });
        std::string file = readFile(dir.path() / "p.vtp");
        // Same length, so every offset stays valid.
        file.replace(file.find("mfdynDimension"), 14, "someOtherValue");
        writeFile(dir.path() / "p.vtp", file);
        EXPECT_EQ(readVtp(dir.path() / "p.vtp").particles->dimension(), dim);
    }
}

TEST(VtpReader, TruncatedFileIsAnErrorNamingTheFile) {
    ScratchDir dir("truncated");
    writeVtp(dir.path() / "p.vtp", makeParticles<3>(100, 3), 0.0);
    const std::string whole = readFile(dir.path() / "p.vtp");
    // Inside the XML header, inside the binary data, and just the closing tags lost.
    for (std::size_t length :
         {std::size_t(0), std::size_t(300), whole.size() / 2, whole.size() - 1000, whole.size() - 12}) {
        const auto cut = dir.path() / "cut.vtp";
        writeFile(cut, whole.substr(0, length));
        try {
            readVtp(cut);
            ADD_FAILURE() << "no error for a file cut at " << length << " of " << whole.size() << " bytes";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(cut.string()), std::string::npos) << e.what();
        }
    }
    try {
        readVtp(dir.path() / "missing.vtp");
        ADD_FAILURE() << "no error for a missing file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.vtp"), std::string::npos) << e.what();
    }
}

TEST(VtpReader, EveryCutOfASmallFileIsReported) {
    // Every length short of the final newline must fail cleanly (and, under a sanitizer, without
    // reading past the buffer).
    ScratchDir dir("everyCut");
    writeVtp(dir.path() / "p.vtp", makeParticles<2>(2, 9), 0.0);
    const std::string whole = readFile(dir.path() / "p.vtp");
    ASSERT_EQ(whole.back(), '\n');
    std::size_t failures = 0;
    for (std::size_t length = 0; length + 1 < whole.size(); ++length) {
        writeFile(dir.path() / "cut.vtp", whole.substr(0, length));
        try {
            readVtp(dir.path() / "cut.vtp");
        } catch (const InputError&) {
            ++failures;
        }
    }
    EXPECT_EQ(failures, whole.size() - 1);
}

TEST(VtpReader, BadXmlAndUnknownTypesAreReported) {
    ScratchDir dir("bad");
    writeVtp(dir.path() / "p.vtp", makeParticles<2>(10, 5), 0.0);
    const std::string whole = readFile(dir.path() / "p.vtp");

    std::string badType = whole;
    badType.replace(badType.find("type=\"Float64\" Name=\"rho\""), 14, "type=\"Float65\"");
    writeFile(dir.path() / "type.vtp", badType);
    try {
        readVtp(dir.path() / "type.vtp");
        ADD_FAILURE() << "no error for an unknown type";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown type 'Float65'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("rho"), std::string::npos) << e.what();
    }

    std::string badXml = whole;
    badXml.replace(badXml.find("<PointData>"), 11, "<PointData<");
    writeFile(dir.path() / "xml.vtp", badXml);
    try {
        readVtp(dir.path() / "xml.vtp");
        ADD_FAILURE() << "no error for bad XML";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("xml.vtp:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad XML"), std::string::npos) << e.what();
    }
}

// 1e6 particles in 3D with a solid-dynamics field set; run with --gtest_also_run_disabled_tests.
TEST(VtpReader, DISABLED_SpeedMillionParticles3D) {
    ScratchDir dir("speed");
    ParticleSet<3> p(1000000);
    for (const char* s : {"rho", "p", "e", "m", "h"}) p.scalarField(s);
    p.vectorField("velocity");
    p.vectorField("acceleration");
    p.tensorField("F");
    p.symmTensorField("sigma");
    p.integerField("material");
    Stopwatch write;
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    const double writeSeconds = write.seconds();
    Stopwatch read;
    ParticleFile back = readVtp(dir.path() / "p.vtp");
    const double readSeconds = read.seconds();
    const auto bytes = std::filesystem::file_size(dir.path() / "p.vtp");
    std::printf("1e6 particles 3D, %zu bytes/particle, file %.0f MB: write %.2f s, read %.2f s\n",
                p.bytesPerParticle(), bytes / 1e6, writeSeconds, readSeconds);
    EXPECT_EQ(back.particles->size(), p.size());
}
