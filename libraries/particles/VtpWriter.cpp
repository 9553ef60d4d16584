#include "particles/VtpWriter.hpp"

#include "core/Error.hpp"
#include "particles/XmlElement.hpp"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <sstream>

namespace mfdyn {

static_assert(std::endian::native == std::endian::little,
              "the particle writer copies memory as it is and declares it LittleEndian");

int vtkComponents(FieldKind kind) {
    switch (kind) {
        case FieldKind::scalar:
        case FieldKind::integer:
            return 1;
        case FieldKind::vector:
            return 3;
        case FieldKind::tensor:
            return 9;
        case FieldKind::symmTensor:
            return 6;
    }
    return 0;
}

std::vector<int> vtkComponentSource(FieldKind kind, int dim) {
    std::vector<int> source;
    switch (kind) {
        case FieldKind::scalar:
        case FieldKind::integer:
            source = {0};
            break;
        case FieldKind::vector:
            for (int k = 0; k < 3; ++k) source.push_back(k < dim ? k : -1);
            break;
        case FieldKind::tensor:
            // File: row-major 3x3. Memory: Eigen column-major dim x dim.
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) source.push_back(i < dim && j < dim ? i + j * dim : -1);
            break;
        case FieldKind::symmTensor: {
            // File: XX YY ZZ XY YZ XZ. Memory: SymmTensor<dim> order (xx yy xy in 2D).
            const int row[] = {0, 1, 2, 0, 1, 0}, col[] = {0, 1, 2, 1, 2, 2};
            for (int k = 0; k < 6; ++k) {
                int i = row[k], j = col[k];
                if (i >= dim || j >= dim)
                    source.push_back(-1);
                else if (i == j)
                    source.push_back(i);
                else if (dim == 2)
                    source.push_back(2);
                else
                    source.push_back(k);
            }
            break;
        }
    }
    return source;
}

namespace {

// One DataArray: its XML attributes, its byte count and how to produce its bytes.
struct Block {
    std::string section;  // FieldData, PointData, Points, Verts
    std::string attributes;
    std::uint64_t bytes = 0;
    std::function<void(std::FILE*)> emit;
};

class Output {
public:
    explicit Output(const std::filesystem::path& file) : file_(file) {
        out_ = std::fopen(file.c_str(), "wb");
        if (!out_) throw Error("cannot write particle file '" + file.string() + "': " + std::strerror(errno));
        // Large blocks go to fwrite directly; the buffer only batches the small writes.
        std::setvbuf(out_, nullptr, _IOFBF, 1 << 20);
    }
    ~Output() {
        if (out_) std::fclose(out_);
    }
    std::FILE* get() const { return out_; }
    void write(const void* data, std::size_t bytes) {
        if (bytes && std::fwrite(data, 1, bytes, out_) != bytes) fail();
    }
    void close() {
        bool bad = std::fflush(out_) != 0 || std::ferror(out_);
        bad = std::fclose(out_) != 0 || bad;
        out_ = nullptr;
        if (bad) fail();
    }

private:
    [[noreturn]] void fail() const {
        throw Error("cannot write particle file '" + file_.string() + "': " + std::strerror(errno));
    }
    std::filesystem::path file_;
    std::FILE* out_ = nullptr;
};

void writeOrThrow(std::FILE* out, const void* data, std::size_t bytes) {
    if (bytes && std::fwrite(data, 1, bytes, out) != bytes)
        throw Error(std::string("write failed: ") + std::strerror(errno));
}

// Writes n elements of `components` values each from `memory`, rearranged by `source` (-1 =
// zero) into chunks, so a padded copy of a large field never has to exist whole.
template <class T>
void emitMapped(std::FILE* out, const T* memory, std::size_t n, int components,
                const std::vector<int>& source) {
    const bool identity = int(source.size()) == components && [&] {
        for (int k = 0; k < components; ++k)
            if (source[k] != k) return false;
        return true;
    }();
    if (identity) return writeOrThrow(out, memory, n * components * sizeof(T));
    const std::size_t width = source.size(), chunk = 1 << 15;
    std::vector<T> buffer(chunk * width);
    for (std::size_t begin = 0; begin < n; begin += chunk) {
        const std::size_t count = std::min(chunk, n - begin);
        for (std::size_t i = 0; i < count; ++i) {
            const T* in = memory + (begin + i) * components;
            T* to = buffer.data() + i * width;
            for (std::size_t k = 0; k < width; ++k) to[k] = source[k] < 0 ? T(0) : in[source[k]];
        }
        writeOrThrow(out, buffer.data(), count * width * sizeof(T));
    }
}

std::string arrayAttributes(const std::string& type, const std::string& name, int components) {
    return "type=\"" + type + "\" Name=\"" + xmlEscape(name) + "\" NumberOfComponents=\"" +
           std::to_string(components) + "\"";
}

std::string fieldAttributes(const FieldBase& f) {
    return arrayAttributes(f.isInteger() ? "Int64" : "Float64", f.name(), vtkComponents(f.kind()));
}

Block fieldBlock(const std::string& section, const FieldBase& f, std::size_t n) {
    Block b;
    b.section = section;
    const int width = vtkComponents(f.kind());
    b.attributes = fieldAttributes(f);
    b.bytes = std::uint64_t(n) * width * 8;
    b.emit = [&f, n, source = vtkComponentSource(f.kind(), f.dimension())](std::FILE* out) {
        if (f.isInteger())
            emitMapped(out, static_cast<const std::int64_t*>(f.data()), n, 1, source);
        else
            emitMapped(out, static_cast<const double*>(f.data()), n, f.components(), source);
    };
    return b;
}

Block vertsBlock(const std::string& name, std::size_t n, std::int64_t first) {
    Block b;
    b.section = "Verts";
    b.attributes = arrayAttributes("Int64", name, 1);
    b.bytes = std::uint64_t(n) * 8;
    b.emit = [n, first](std::FILE* out) {
        std::vector<std::int64_t> buffer(std::min<std::size_t>(n, 1 << 15));
        for (std::size_t begin = 0; begin < n; begin += buffer.size()) {
            const std::size_t count = std::min(buffer.size(), n - begin);
            for (std::size_t i = 0; i < count; ++i) buffer[i] = first + std::int64_t(begin + i);
            writeOrThrow(out, buffer.data(), count * 8);
        }
    };
    return b;
}

Block stringsBlock(const std::string& name, const std::vector<std::string>& strings) {
    Block b;
    b.section = "FieldData";
    std::string bytes;
    for (const auto& s : strings) {
        if (s.find('\0') != std::string::npos) throw Error("name in '" + name + "' contains a NUL character");
        bytes += s;
        bytes += '\0';
    }
    b.attributes =
        "type=\"String\" Name=\"" + name + "\" NumberOfTuples=\"" + std::to_string(strings.size()) + "\"";
    b.bytes = bytes.size();
    b.emit = [bytes = std::move(bytes)](std::FILE* out) { writeOrThrow(out, bytes.data(), bytes.size()); };
    return b;
}

template <class T>
Block valueBlock(const std::string& type, const std::string& name, T value) {
    Block b;
    b.section = "FieldData";
    b.attributes = "type=\"" + type + "\" Name=\"" + name + "\" NumberOfTuples=\"1\"";
    b.bytes = sizeof(T);
    b.emit = [value](std::FILE* out) { writeOrThrow(out, &value, sizeof(T)); };
    return b;
}

}  // namespace

void writeVtp(const std::filesystem::path& file, const ParticleSetBase& particles, double time,
              std::int64_t runNextGlobalId) {
    // Owned particles only: ghosts are remade from them each step (ParticleSetBase).
    const std::size_t n = particles.ownedCount();
    const FieldBase& position = particles.field("position");

    std::vector<Block> blocks;
    blocks.push_back(valueBlock<std::int32_t>("Int32", "mfdynDimension", particles.dimension()));
    blocks.push_back(valueBlock<double>("Float64", "time", time));
    // The next global id, only when the ids alone do not imply it (the particle of the highest
    // id was removed): a run restarted from this file then still never reuses an id. Files of
    // runs that remove nothing are unchanged.
    {
        const auto& id = particles.requireField<std::int64_t>("globalId");
        std::int64_t implied = 0;
        for (std::size_t i = 0; i < n; ++i) implied = std::max(implied, id[i] + 1);
        const std::int64_t next = std::max(particles.nextGlobalId(), runNextGlobalId);
        if (next > implied) blocks.push_back(valueBlock<std::int64_t>("Int64", "nextGlobalId", next));
    }
    if (!particles.regionNames.empty()) blocks.push_back(stringsBlock("regionNames", particles.regionNames));
    if (!particles.materialNames.empty())
        blocks.push_back(stringsBlock("materialNames", particles.materialNames));
    for (const auto& f : particles.fields())
        if (f.get() != &position) blocks.push_back(fieldBlock("PointData", *f, n));
    blocks.push_back(fieldBlock("Points", position, n));
    blocks.push_back(vertsBlock("connectivity", n, 0));
    blocks.push_back(vertsBlock("offsets", n, 1));

    std::uint64_t offset = 0;
    std::ostringstream xml;
    auto section = [&](const std::string& name, const std::string& indent) {
        for (const Block& b : blocks) {
            if (b.section != name) continue;
            xml << indent << "<DataArray " << b.attributes << " format=\"appended\" offset=\"" << offset
                << "\"/>\n";
            offset += sizeof(std::uint64_t) + b.bytes;
        }
    };
    // The sections are written to the header in the same order as `blocks`, so offsets follow.
    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "  <PolyData>\n    <FieldData>\n";
    section("FieldData", "      ");
    xml << "    </FieldData>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "      <PointData>\n";
    section("PointData", "        ");
    xml << "      </PointData>\n      <Points>\n";
    section("Points", "        ");
    xml << "      </Points>\n      <Verts>\n";
    section("Verts", "        ");
    xml << "      </Verts>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

    Output out(file);
    const std::string header = xml.str();
    out.write(header.data(), header.size());
    try {
        for (const char* name : {"FieldData", "PointData", "Points", "Verts"}) {
            for (const Block& b : blocks) {
                if (b.section != name) continue;
                out.write(&b.bytes, sizeof b.bytes);
                b.emit(out.get());
            }
        }
    } catch (const Error& e) {
        throw Error("cannot write particle file '" + file.string() + "': " + e.what());
    }
    const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
    out.write(tail.data(), tail.size());
    out.close();
}

std::vector<std::string> pointDataAttributes(const ParticleSetBase& particles) {
    const FieldBase& position = particles.field("position");
    std::vector<std::string> attributes;
    for (const auto& f : particles.fields())
        if (f.get() != &position) attributes.push_back(fieldAttributes(*f));
    return attributes;
}

void writePvtp(const std::filesystem::path& file, const ParticleSetBase& particles,
               const std::vector<std::string>& pieces) {
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
    for (const std::string& attributes : pointDataAttributes(particles))
        xml << "      <PDataArray " << attributes << "/>\n";
    xml << "    </PPointData>\n    <PPoints>\n"
        << "      <PDataArray " << fieldAttributes(particles.field("position")) << "/>\n"
        << "    </PPoints>\n";
    for (const std::string& piece : pieces) xml << "    <Piece Source=\"" << xmlEscape(piece) << "\"/>\n";
    xml << "  </PPolyData>\n</VTKFile>\n";
    Output out(file);
    const std::string text = xml.str();
    out.write(text.data(), text.size());
    out.close();
}

}  // namespace mfdyn
