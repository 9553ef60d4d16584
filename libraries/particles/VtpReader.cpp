#include "particles/VtpReader.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/RegularFile.hpp"
#include "particles/VtpWriter.hpp"
#include "particles/XmlElement.hpp"

#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <set>

namespace mfdyn {

namespace {

enum class Scalar { float32, float64, int8, int16, int32, int64, uint8, uint16, uint32, uint64, string };

struct ScalarType {
    const char* name;
    Scalar scalar;
    std::size_t bytes;
};

constexpr ScalarType scalarTypes[] = {
    {"Float32", Scalar::float32, 4}, {"Float64", Scalar::float64, 8}, {"Int8", Scalar::int8, 1},
    {"Int16", Scalar::int16, 2},     {"Int32", Scalar::int32, 4},     {"Int64", Scalar::int64, 8},
    {"UInt8", Scalar::uint8, 1},     {"UInt16", Scalar::uint16, 2},   {"UInt32", Scalar::uint32, 4},
    {"UInt64", Scalar::uint64, 8},   {"String", Scalar::string, 1},
};

bool isFloat(Scalar s) {
    return s == Scalar::float32 || s == Scalar::float64;
}

// No VTK array mfdyn reads has more than 9 components (a tensor); the bound keeps sizes derived
// from NumberOfComponents small and their products free of overflow.
constexpr std::int64_t maxComponents = 64;
// mfdyn writes a few dozen fields. Fields are found by name in a list, so a header of 10^5
// arrays (all of them may share one offset) would take 10^10 comparisons: refused instead.
constexpr std::size_t maxPointArrays = 1024;

// One appended array located in the file and checked against its size.
struct Array {
    std::string name;
    ScalarType type;
    int components = 1;
    const char* bytes = nullptr;  // unaligned
    std::uint64_t byteCount = 0;
};

class Reader {
public:
    explicit Reader(const std::filesystem::path& file) : file_(file) {}

    ParticleFile read() {
        contents_ = std::make_unique<RegularFile>(file_);  // a FIFO is an error, not a wait
        buffer_ = contents_->data();
        size_ = contents_->size();
        std::size_t stop = 0;
        const XmlElement root =
            XmlElement::parse(std::string_view(buffer_, size_), file_.string(), "AppendedData", &stop);
        checkHeader(root);
        const XmlElement& polyData = child(root, "PolyData");
        const XmlElement* appended = nullptr;
        for (const auto& c : root.children)
            if (c.name == "AppendedData") appended = &c;
        if (!appended) fail("no <AppendedData> element");
        if (const std::string* enc = appended->findAttribute("encoding"); !enc || *enc != "raw")
            fail("appended data encoding '" + (enc ? *enc : std::string("base64")) +
                 "' is not supported (mfdyn reads raw appended data)");
        while (stop < size_ && std::isspace(static_cast<unsigned char>(buffer_[stop]))) ++stop;
        if (stop >= size_ || buffer_[stop] != '_')
            fail("truncated or malformed: no '_' starting the appended data");
        dataStart_ = stop + 1;
        // The arrays' own sizes catch a cut inside the data; this catches a cut after it.
        std::size_t end = size_;
        while (end > dataStart_ && std::isspace(static_cast<unsigned char>(buffer_[end - 1]))) --end;
        if (!std::string_view(buffer_ + dataStart_, end - dataStart_).ends_with("</VTKFile>"))
            fail("truncated: the file does not end with </VTKFile>");

        auto pieces = polyData.childrenNamed("Piece");
        if (pieces.size() != 1) fail("expected one <Piece>, found " + std::to_string(pieces.size()));
        const XmlElement& piece = *pieces[0];
        const std::size_t n = std::size_t(integerAttribute(piece, "NumberOfPoints"));

        ParticleFile result;
        int dim = 0;
        std::vector<std::string> regionNames, materialNames;
        std::int64_t nextGlobalId = 0;  // a floor only; the ids read raise it (ParticleSetBase)
        if (const XmlElement* fieldData = polyData.findChild("FieldData")) {
            for (const XmlElement* e : fieldData->childrenNamed("DataArray")) {
                const std::string name = attribute(*e, "Name");
                if (name == "mfdynDimension") {
                    // Checked as a double: converting NaN or 1e300 to int is undefined.
                    const double value = singleValue(*e);
                    if (!(value == 1 || value == 2 || value == 3))
                        fail("mfdynDimension is " + formatNumber(value) + ", not 1, 2 or 3");
                    dim = int(value);
                } else if (name == "time") {
                    result.time = singleValue(*e);
                    if (!std::isfinite(result.time)) fail("time is " + formatNumber(result.time));
                    result.hasTime = true;
                } else if (name == "nextGlobalId") {
                    // Checked as a double (as mfdynDimension); ids up to 2^53 are exact.
                    const double value = singleValue(*e);
                    if (!(value >= 0 && value <= 9007199254740992.0 && value == std::floor(value)))
                        fail("nextGlobalId is " + formatNumber(value) +
                             ", not a whole number from 0 to 2^53");
                    nextGlobalId = std::int64_t(value);
                } else if (name == "regionNames")
                    regionNames = strings(*e);
                else if (name == "materialNames")
                    materialNames = strings(*e);
            }
        }

        const XmlElement& pointsArray = child(child(piece, "Points"), "DataArray");
        const Array points = locate(pointsArray, n);
        if (!isFloat(points.type.scalar) || points.components != 3)
            fail("Points must be Float32 or Float64 with 3 components");
        if (dim == 0) dim = inferDimension(points, n);
        if (dim < 1 || dim > 3) fail("mfdynDimension is " + std::to_string(dim) + ", not 1, 2 or 3");

        std::vector<Array> arrays;
        std::set<std::string> names;
        if (const XmlElement* pointData = piece.findChild("PointData"))
            for (const XmlElement* e : pointData->childrenNamed("DataArray")) {
                if (arrays.size() == maxPointArrays)
                    fail("more than " + std::to_string(maxPointArrays) + " PointData arrays (line " +
                         std::to_string(e->line) + "); mfdyn reads at most that many fields");
                arrays.push_back(locate(*e, n));
                // Two arrays of one name would silently overwrite each other.
                if (!names.insert(arrays.back().name).second)
                    fail("PointData array '" + arrays.back().name + "' appears twice (line " +
                         std::to_string(e->line) + ")");
            }

        result.particles = withDimension(dim, [&](auto d) -> std::unique_ptr<ParticleSetBase> {
            constexpr int Dim = decltype(d)::value;
            auto set = std::make_unique<ParticleSet<Dim>>(n);
            copy(points, set->field("position"), n);
            bool haveId = false;
            for (const Array& a : arrays) {
                if (a.name == "position") fail("PointData array 'position' clashes with the Points");
                const FieldKind kind = kindOf(a);
                FieldBase* f = set->findField(a.name);
                if (!f)
                    f = &set->addField(a.name, kind);
                else if (f->kind() != kind)
                    fail("array '" + a.name + "' is a " + kindName(kind) + " but mfdyn keeps it as " +
                         kindName(f->kind()));
                haveId = haveId || a.name == "globalId";
                copy(a, *f, n);
            }
            if (!haveId) {
                auto& id = set->globalId();
                for (std::size_t i = 0; i < n; ++i) id[i] = std::int64_t(i);
            }
            checkRegions(set->region(), regionNames.size());
            return set;
        });
        result.particles->regionNames = std::move(regionNames);
        result.particles->materialNames = std::move(materialNames);
        result.particles->reserveGlobalIdsBelow(nextGlobalId);
        // Fields read here that a model then asks for with another type are the file's fault:
        // the clash is reported as an InputError naming this file.
        result.particles->setSource(file_.string());
        return result;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("particle file '" + file_.string() + "': " + what);
    }

    void checkHeader(const XmlElement& root) {
        if (root.name != "VTKFile") fail("root element is <" + root.name + ">, not <VTKFile>");
        if (const std::string* type = root.findAttribute("type"); !type || *type != "PolyData")
            fail("VTKFile type is '" + (type ? *type : std::string()) + "', not 'PolyData'");
        if (const std::string* order = root.findAttribute("byte_order"); order && *order != "LittleEndian")
            fail("byte_order '" + *order + "' is not supported");
        if (root.findAttribute("compressor")) fail("compressed files are not supported");
        if (const std::string* header = root.findAttribute("header_type")) {
            if (*header == "UInt64")
                headerBytes_ = 8;
            else if (*header == "UInt32")
                headerBytes_ = 4;
            else
                fail("unknown header_type '" + *header + "'");
        }
    }

    static std::string formatNumber(double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", v);
        return text;
    }

    // Region ids index regionNames and size per-region tables (particleInfo's counts): a
    // corrupt id of 4e8 would make those allocate gigabytes. Ids from 0 to the larger of the
    // particle count and the number of region names are accepted (ids beyond the names are
    // unnamed regions), which keeps any such table no larger than the particle data.
    void checkRegions(const std::vector<std::int64_t>& region, std::size_t names) const {
        const std::size_t limit = std::max(region.size(), names);
        for (std::size_t i = 0; i < region.size(); ++i)
            if (region[i] < 0 || std::uint64_t(region[i]) >= limit)
                fail("particle " + std::to_string(i) + " has region id " + std::to_string(region[i]) +
                     "; with " + std::to_string(region.size()) + " particles and " + std::to_string(names) +
                     " region names, region ids run from 0 to " + std::to_string(limit - 1));
    }

    const XmlElement& child(const XmlElement& parent, std::string_view name) const {
        if (const XmlElement* c = parent.findChild(name)) return *c;
        fail("<" + parent.name + "> (line " + std::to_string(parent.line) + ") has no <" + std::string(name) +
             ">");
    }

    std::string attribute(const XmlElement& e, std::string_view key) const {
        if (const std::string* v = e.findAttribute(key)) return *v;
        fail("<" + e.name + "> at line " + std::to_string(e.line) + " has no attribute '" + std::string(key) +
             "'");
    }

    std::int64_t integerAttribute(const XmlElement& e, std::string_view key) const {
        const std::string text = attribute(e, key);
        std::int64_t value = 0;
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || value < 0)
            fail("<" + e.name + "> at line " + std::to_string(e.line) + ": " + std::string(key) + "=\"" +
                 text + "\" is not a non-negative integer");
        return value;
    }

    Array locate(const XmlElement& e, std::size_t tuples) const {
        Array a;
        a.name = attribute(e, "Name");
        const std::string where = "array '" + a.name + "' (line " + std::to_string(e.line) + ")";
        const std::string type = attribute(e, "type");
        bool known = false;
        for (const ScalarType& t : scalarTypes)
            if (type == t.name) {
                a.type = t;
                known = true;
            }
        if (!known) fail(where + " has unknown type '" + type + "'");
        if (const std::string* format = e.findAttribute("format"); !format || *format != "appended")
            fail(where + " has format '" + (format ? *format : std::string()) +
                 "'; only appended data is supported");
        if (e.findAttribute("NumberOfComponents")) {
            const std::int64_t components = integerAttribute(e, "NumberOfComponents");
            if (components < 1 || components > maxComponents)
                fail(where + " has NumberOfComponents=\"" + attribute(e, "NumberOfComponents") +
                     "\"; it must be 1 to " + std::to_string(maxComponents));
            a.components = int(components);
        }
        // Every size below is compared by subtraction from what the file holds, never by adding
        // a number from the file to another: a sum can wrap around 2^64 and pass the check
        // (a NumberOfPoints near 2^61 did, and the reader then ran through memory).
        const std::uint64_t offset = std::uint64_t(integerAttribute(e, "offset"));
        const std::uint64_t data = size_ - dataStart_;  // dataStart_ <= size_ (checked in read())
        if (offset > data || data - offset < headerBytes_)
            fail("truncated: " + where + " starts at byte " + std::to_string(offset) +
                 " of the appended data, but the file has " + std::to_string(data) + " bytes of it");
        const std::uint64_t begin = dataStart_ + offset;
        if (headerBytes_ == 8) {
            std::memcpy(&a.byteCount, buffer_ + begin, 8);
        } else {
            std::uint32_t count;
            std::memcpy(&count, buffer_ + begin, 4);
            a.byteCount = count;
        }
        const std::uint64_t left = size_ - begin - headerBytes_;
        if (a.byteCount > left)
            fail("truncated: " + where + " says it holds " + std::to_string(a.byteCount) +
                 " bytes but only " + std::to_string(left) + " follow in the file");
        a.bytes = buffer_ + begin + headerBytes_;
        if (a.type.scalar != Scalar::string) {
            const std::uint64_t perTuple = std::uint64_t(a.components) * a.type.bytes;  // <= 64 x 8
            if (std::uint64_t(tuples) > left / perTuple)
                fail(where + ": " + std::to_string(tuples) + " tuples x " + std::to_string(a.components) +
                     " components x " + std::to_string(a.type.bytes) + " bytes exceed the " +
                     std::to_string(left) + " bytes left in the file (NumberOfPoints or " +
                     "NumberOfComponents is wrong)");
            const std::uint64_t expected = std::uint64_t(tuples) * perTuple;
            if (a.byteCount != expected)
                fail(where + " holds " + std::to_string(a.byteCount) + " bytes; " + std::to_string(tuples) +
                     " x " + std::to_string(a.components) + " " + a.type.name + " need " +
                     std::to_string(expected));
        }
        return a;
    }

    double singleValue(const XmlElement& e) const {
        const Array a = locate(e, 1);
        if (a.type.scalar == Scalar::string) fail("array '" + a.name + "' should be numeric");
        return valueAsDouble(a, 0);
    }

    std::vector<std::string> strings(const XmlElement& e) const {
        const Array a = locate(e, 0);
        if (a.type.scalar != Scalar::string) fail("array '" + a.name + "' should be of type String");
        std::vector<std::string> out;
        std::size_t start = 0;
        for (std::size_t i = 0; i < a.byteCount; ++i)
            if (a.bytes[i] == '\0') {
                out.emplace_back(a.bytes + start, i - start);
                start = i + 1;
            }
        if (start != a.byteCount) fail("array '" + a.name + "': last string is not NUL-terminated");
        if (e.findAttribute("NumberOfTuples") &&
            out.size() != std::size_t(integerAttribute(e, "NumberOfTuples")))
            fail("array '" + a.name + "' holds " + std::to_string(out.size()) +
                 " strings, NumberOfTuples says " + attribute(e, "NumberOfTuples"));
        return out;
    }

    template <class T>
    static T load(const char* p) {
        T v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }

    static double valueAsDouble(const Array& a, std::size_t k) {
        const char* p = a.bytes + k * a.type.bytes;
        switch (a.type.scalar) {
            case Scalar::float32:
                return load<float>(p);
            case Scalar::float64:
                return load<double>(p);
            case Scalar::int8:
                return load<std::int8_t>(p);
            case Scalar::int16:
                return load<std::int16_t>(p);
            case Scalar::int32:
                return load<std::int32_t>(p);
            case Scalar::int64:
                return double(load<std::int64_t>(p));
            case Scalar::uint8:
                return load<std::uint8_t>(p);
            case Scalar::uint16:
                return load<std::uint16_t>(p);
            case Scalar::uint32:
                return load<std::uint32_t>(p);
            case Scalar::uint64:
                return double(load<std::uint64_t>(p));
            case Scalar::string:
                break;
        }
        return 0.0;
    }

    static std::int64_t valueAsInteger(const Array& a, std::size_t k) {
        const char* p = a.bytes + k * a.type.bytes;
        switch (a.type.scalar) {
            case Scalar::int8:
                return load<std::int8_t>(p);
            case Scalar::int16:
                return load<std::int16_t>(p);
            case Scalar::int32:
                return load<std::int32_t>(p);
            case Scalar::int64:
                return load<std::int64_t>(p);
            case Scalar::uint8:
                return load<std::uint8_t>(p);
            case Scalar::uint16:
                return load<std::uint16_t>(p);
            case Scalar::uint32:
                return load<std::uint32_t>(p);
            case Scalar::uint64:
                return std::int64_t(load<std::uint64_t>(p));
            default:
                break;
        }
        return 0;
    }

    FieldKind kindOf(const Array& a) const {
        if (a.type.scalar == Scalar::string) fail("PointData array '" + a.name + "' is of type String");
        if (!isFloat(a.type.scalar)) {
            if (a.components != 1)
                fail("integer array '" + a.name + "' has " + std::to_string(a.components) +
                     " components; integer fields have 1");
            return FieldKind::integer;
        }
        switch (a.components) {
            case 1:
                return FieldKind::scalar;
            case 3:
                return FieldKind::vector;
            case 6:
                return FieldKind::symmTensor;
            case 9:
                return FieldKind::tensor;
        }
        fail("array '" + a.name + "' has " + std::to_string(a.components) +
             " components; fields have 1 (scalar), 3 (vector), 6 (symmTensor) or 9 (tensor)");
    }

    int inferDimension(const Array& points, std::size_t n) const {
        bool y = false, z = false;
        for (std::size_t i = 0; i < n; ++i) {
            y = y || valueAsDouble(points, 3 * i + 1) != 0.0;
            z = z || valueAsDouble(points, 3 * i + 2) != 0.0;
        }
        return z ? 3 : y ? 2 : 1;
    }

    // File array -> field, through the same component map as the writer.
    void copy(const Array& a, FieldBase& f, std::size_t n) const {
        const std::vector<int> source = vtkComponentSource(f.kind(), f.dimension());
        const int width = a.components, components = f.components();
        if (n == 0) return;  // empty vectors may have null data, which memcpy must not see
        if (f.isInteger()) {
            auto* out = static_cast<std::int64_t*>(f.data());
            if (a.type.scalar == Scalar::int64) return void(std::memcpy(out, a.bytes, n * 8));
            return parallelFor(n, [&](std::size_t i) { out[i] = valueAsInteger(a, i); });
        }
        auto* out = static_cast<double*>(f.data());
        bool identity = a.type.scalar == Scalar::float64 && width == components;
        for (int k = 0; k < width && identity; ++k) identity = source[k] == k;
        if (identity) return void(std::memcpy(out, a.bytes, n * width * 8));
        parallelFor(n, [&](std::size_t i) {
            for (int k = 0; k < width; ++k)
                if (source[k] >= 0) out[i * components + source[k]] = valueAsDouble(a, i * width + k);
        });
    }

    std::filesystem::path file_;
    std::unique_ptr<RegularFile> contents_;
    const char* buffer_ = nullptr;  // contents_'s bytes
    std::size_t size_ = 0;
    std::size_t dataStart_ = 0;
    std::size_t headerBytes_ = 4;
};

}  // namespace

ParticleFile readVtp(const std::filesystem::path& file) {
    try {
        return Reader(file).read();
    } catch (const std::bad_alloc&) {
        // Every size is checked against the file's, so this is a file genuinely larger than
        // the memory there is; still the file's matter, not an internal error.
        throw InputError("particle file '" + file.string() +
                         "': its particles need more memory than there is");
    }
}

}  // namespace mfdyn
