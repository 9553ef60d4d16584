#include "particles/VtpReader.hpp"

#include "TestFiles.hpp"
#include "core/Log.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/VtpWriter.hpp"
#include "particles/XmlElement.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
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
    // Region ids index the region names: the reader accepts 0 up to the larger of the particle
    // count and the number of names, so they are the one integer field not left random.
    for (std::size_t i = 0; i < n; ++i) p.region()[i] = std::int64_t((i * 7919) % n);
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

namespace {

// The byte offset in `file` of the appended data of array `name` (its UInt64 byte count).
std::size_t arrayStart(const std::string& file, const std::string& name) {
    std::size_t stop = 0;
    const XmlElement root = XmlElement::parse(file, "test", "AppendedData", &stop);
    const std::size_t data = file.find('_', stop) + 1;
    std::vector<const XmlElement*> todo{&root};
    while (!todo.empty()) {
        const XmlElement* e = todo.back();
        todo.pop_back();
        if (e->name == "DataArray" && *e->findAttribute("Name") == name)
            return data + std::size_t(std::stoull(*e->findAttribute("offset")));
        for (const auto& c : e->children) todo.push_back(&c);
    }
    ADD_FAILURE() << "no array " << name;
    return 0;
}

// readVtp's InputError message for `file`, or "" (with a test failure) when it reads.
std::string readError(const std::filesystem::path& file) {
    try {
        readVtp(file);
        ADD_FAILURE() << "no error for " << file;
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(VtpReader, HugeNumberOfPointsIsRefusedWithoutOverflow) {
    // 2^61 points x 3 x 8 bytes is 3 x 2^64: 0 after wrap-around, which matched the 0-byte arrays
    // of an empty file on a668953, so the reader went on to allocate or run through 2^61 points.
    ScratchDir dir("hugeN");
    writeVtp(dir.path() / "p.vtp", makeParticles<3>(0, 1), 0.0);
    std::string file = readFile(dir.path() / "p.vtp");
    const std::string huge = "2305843009213693952";  // 2^61
    file.replace(file.find("NumberOfPoints=\"0\""), 18, "NumberOfPoints=\"" + huge + "\"");
    writeFile(dir.path() / "huge.vtp", file);
    const std::string what = readError(dir.path() / "huge.vtp");
    EXPECT_NE(what.find(dir.path().string() + "/huge.vtp"), std::string::npos) << what;
    EXPECT_NE(what.find(huge + " tuples"), std::string::npos) << what;
    EXPECT_NE(what.find("bytes left in the file"), std::string::npos) << what;
}

TEST(VtpReader, HugeByteCountIsRefusedWithoutOverflow) {
    // A byte count near 2^64 wrapped past the end-of-file check; for the region names (a String
    // array, not checked against a tuple count) the reader then read far beyond the file.
    ScratchDir dir("hugeCount");
    writeVtp(dir.path() / "p.vtp", makeParticles<2>(5, 2), 0.0);
    std::string file = readFile(dir.path() / "p.vtp");
    const std::uint64_t count = ~std::uint64_t(0) - 15;
    std::memcpy(file.data() + arrayStart(file, "regionNames"), &count, 8);
    writeFile(dir.path() / "count.vtp", file);
    const std::string what = readError(dir.path() / "count.vtp");
    EXPECT_NE(what.find("count.vtp"), std::string::npos) << what;
    EXPECT_NE(what.find("regionNames"), std::string::npos) << what;
    EXPECT_NE(what.find("says it holds " + std::to_string(count) + " bytes"), std::string::npos) << what;
}

TEST(VtpReader, HugeComponentCountIsRefused) {
    ScratchDir dir("hugeComponents");
    writeVtp(dir.path() / "p.vtp", makeParticles<3>(4, 3), 0.0);
    std::string file = readFile(dir.path() / "p.vtp");
    // 2^62 + 1 components: int() of it was 1, so the array was taken for a scalar.
    const std::size_t at = file.find("NumberOfComponents=\"3\"", file.find("Name=\"velocity\""));
    file.replace(at, 22, "NumberOfComponents=\"4611686018427387905\"");
    writeFile(dir.path() / "c.vtp", file);
    const std::string what = readError(dir.path() / "c.vtp");
    EXPECT_NE(what.find("velocity"), std::string::npos) << what;
    EXPECT_NE(what.find("NumberOfComponents=\"4611686018427387905\"; it must be 1 to 64"), std::string::npos)
        << what;
}

TEST(VtpReader, RegionIdOutOfRangeIsAnErrorNamingTheFile) {
    // A corrupt region id of 4e8 made particleInfo's per-region table allocate 3.2 GB.
    ScratchDir dir("region");
    ParticleSet<2> p(3);
    p.region() = {0, 400000000, 1};
    p.regionNames = {"a", "b"};
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    const std::string what = readError(dir.path() / "p.vtp");
    EXPECT_NE(what.find(dir.path().string() + "/p.vtp"), std::string::npos) << what;
    EXPECT_NE(what.find("particle 1 has region id 400000000"), std::string::npos) << what;
    EXPECT_NE(what.find("region ids run from 0 to 2"), std::string::npos) << what;
    p.region() = {0, -1, 1};
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    EXPECT_NE(readError(dir.path() / "p.vtp").find("region id -1"), std::string::npos);
    // Ids beyond the names but within the particle count are unnamed regions, still read.
    p.region() = {0, 2, 1};
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    EXPECT_EQ(readVtp(dir.path() / "p.vtp").particles->regionCounts(), (std::vector<std::size_t>{1, 1, 1}));
}

TEST(VtpReader, NonFiniteTimeIsAnError) {
    ScratchDir dir("nanTime");
    writeVtp(dir.path() / "p.vtp", ParticleSet<1>(2), std::numeric_limits<double>::quiet_NaN());
    const std::string what = readError(dir.path() / "p.vtp");
    EXPECT_NE(what.find("p.vtp': time is nan"), std::string::npos) << what;
}

TEST(VtpReader, RepeatedArrayIsAnError) {
    ScratchDir dir("repeated");
    ParticleSet<1> p(2);
    p.scalarField("rho");
    p.scalarField("rhx");
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    std::string file = readFile(dir.path() / "p.vtp");
    file.replace(file.find("Name=\"rhx\""), 10, "Name=\"rho\"");
    writeFile(dir.path() / "p.vtp", file);
    EXPECT_NE(readError(dir.path() / "p.vtp").find("PointData array 'rho' appears twice"), std::string::npos);
}

TEST(VtpReader, FifoIsRefusedWithoutBlocking) {
    // On a668953 fopen() of a FIFO waited for a writer that never came.
    ScratchDir dir("fifo");
    const auto file = dir.path() / "particles.vtp";
    const auto result = mfdyn::test::readFifo(file, [&] { readVtp(file); });
    EXPECT_FALSE(result.blocked) << "the read blocked for " << result.seconds << " s";
    EXPECT_NE(result.message.find("'" + file.string() + "' is not a regular file"), std::string::npos)
        << result.message;
    EXPECT_NE(readError(dir.path()).find("is not a regular file (it is a directory)"), std::string::npos);
}

TEST(VtpReader, FieldOfTheWrongKindNamesTheFile) {
    // On a668953: "field 'velocity' is a scalar but was asked for as a vector<2>", an Error with
    // no file, though the file is what is wrong.
    ScratchDir dir("wrongKind");
    ParticleSet<2> p(3);
    p.scalarField("velocity");
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    ParticleFile back = readVtp(dir.path() / "p.vtp");
    auto& particles = particleSetCast<2>(*back.particles);
    try {
        particles.vectorField("velocity");
        ADD_FAILURE() << "a scalar taken for a vector";
    } catch (const InputError& e) {
        EXPECT_EQ(
            std::string(e.what()),
            "particle file '" + (dir.path() / "p.vtp").string() +
                "': field 'velocity' is a scalar (1 component in the file) but is needed as a vector<2> "
                "(3 components in a particle file)");
    }
    // A field the code made itself keeps the plain Error: there the code is wrong, not a file.
    particles.scalarField("made");
    try {
        particles.vectorField("made");
        ADD_FAILURE() << "a scalar taken for a vector";
    } catch (const InputError& e) {
        ADD_FAILURE() << "blamed on the file: " << e.what();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find("particle file"), std::string::npos) << e.what();
    }
}

TEST(VtpReader, MutatedFilesAreReadOrRefusedCleanly) {
    // A fixed-seed mutation loop over a written file: bit flips, hostile numbers in the header,
    // cuts, deletions, insertions and corrupted byte counts. Every outcome must be a particle set
    // or an InputError naming the file: no crash, no hang, no other exception. (Run it under
    // AddressSanitizer to see reads beyond the buffer.)
    ScratchDir dir("mutate");
    auto particles = makeParticles<3>(6, 11);
    writeVtp(dir.path() / "p.vtp", particles, 0.5);
    const std::string whole = readFile(dir.path() / "p.vtp");
    const std::size_t header = whole.find("<AppendedData");
    const auto file = dir.path() / "m.vtp";
    const char* numbers[] = {
        "-1",        "0",   "nan", "1e300", "18446744073709551615", "2305843009213693952",
        "999999999", "4e8", "+3",  " 3",    "9223372036854775807",  "-9223372036854775808"};
    const std::uint64_t counts[] = {
        0, 1, 7, 8, 0xFFFFFFFF, ~std::uint64_t(0), ~std::uint64_t(0) - 7, std::uint64_t(1) << 61};
    std::mt19937_64 rng(1414);
    std::size_t read = 0, refused = 0;
    for (int m = 0; m < 400; ++m) {
        std::string text = whole;
        std::string what;
        switch (m % 7) {
            case 0: {  // a bit flip anywhere
                const std::size_t at = rng() % text.size();
                text[at] = char(text[at] ^ (1 << (rng() % 8)));
                what = "bit flip at " + std::to_string(at);
                break;
            }
            case 1: {  // a number of the header replaced by a hostile one
                std::vector<std::size_t> digits;
                for (std::size_t i = 0; i < header; ++i)
                    if (std::isdigit(static_cast<unsigned char>(text[i])) && text[i - 1] == '"')
                        digits.push_back(i);
                const std::size_t at = digits[rng() % digits.size()];
                const std::size_t end = text.find('"', at);
                const char* number = numbers[rng() % std::size(numbers)];
                text.replace(at, end - at, number);
                what = "number at " + std::to_string(at) + " -> " + number;
                break;
            }
            case 2: {  // cut
                const std::size_t at = rng() % text.size();
                text.resize(at);
                what = "cut at " + std::to_string(at);
                break;
            }
            case 3: {  // a range deleted
                const std::size_t at = rng() % text.size();
                text.erase(at, 1 + rng() % 64);
                what = "erase at " + std::to_string(at);
                break;
            }
            case 4: {  // a range duplicated
                const std::size_t at = rng() % text.size();
                text.insert(at, text.substr(at, 1 + rng() % 64));
                what = "duplicate at " + std::to_string(at);
                break;
            }
            case 5: {  // an array's byte count corrupted
                const char* names[] = {"position",    "rho",  "velocity",      "F",
                                       "regionNames", "time", "mfdynDimension"};
                const char* name = names[rng() % std::size(names)];
                const std::uint64_t count = counts[rng() % std::size(counts)];
                std::memcpy(text.data() + arrayStart(whole, name), &count, 8);
                what = std::string("byte count of ") + name + " -> " + std::to_string(count);
                break;
            }
            case 6: {  // random bytes over a stretch of the header
                const std::size_t at = rng() % header;
                for (std::size_t k = at; k < std::min(header, at + 1 + rng() % 8); ++k) text[k] = char(rng());
                what = "random bytes at " + std::to_string(at);
                break;
            }
        }
        writeFile(file, text);
        try {
            const ParticleFile back = readVtp(file);
            ++read;
            for (const auto& f : back.particles->fields())
                EXPECT_EQ(f->size(), back.particles->size()) << what;
            EXPECT_NO_THROW(back.particles->regionCounts()) << what;
        } catch (const InputError& e) {
            ++refused;
            EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos)
                << what << ": " << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << what << ": not an InputError: " << e.what();
        }
    }
    std::printf("%zu mutations read, %zu refused\n", read, refused);
    EXPECT_GT(refused, 200u) << "most mutations break the file";
    EXPECT_GT(read, 10u) << "flips inside values leave a readable file";
}

TEST(VtpReader, TooManyArraysAreRefused) {
    // Fields are looked up by name in a list: 10^5 arrays (which may all share one offset) were a
    // quadratic wait. 2000 arrays over the same data are refused at the 1025th.
    ScratchDir dir("manyArrays");
    ParticleSet<1> p(2);
    p.scalarField("a");
    writeVtp(dir.path() / "p.vtp", p, 0.0);
    std::string file = readFile(dir.path() / "p.vtp");
    const std::size_t start = file.rfind("<DataArray", file.find("Name=\"a\""));
    const std::size_t end = file.find('\n', start) + 1;
    const std::string line = file.substr(start, end - start);
    std::string copies;
    for (int i = 0; i < 2000; ++i) {
        std::string copy = line;
        copy.replace(copy.find("Name=\"a\""), 8, "Name=\"a" + std::to_string(i) + "\"");
        copies += copy;
    }
    file.insert(end, copies);
    writeFile(dir.path() / "p.vtp", file);
    EXPECT_NE(readError(dir.path() / "p.vtp").find("more than 1024 PointData arrays"), std::string::npos);
}
