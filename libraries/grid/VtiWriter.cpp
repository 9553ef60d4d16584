#include "grid/VtiWriter.hpp"

#include "core/Error.hpp"
#include "particles/VtpWriter.hpp"
#include "particles/XmlElement.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace mfdyn {

static_assert(std::endian::native == std::endian::little,
              "the grid writer copies memory as it is and declares it LittleEndian");

namespace {

std::string number17(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

void appendBytes(std::string& out, const void* data, std::size_t bytes) {
    out.append(static_cast<const char*>(data), bytes);
}

// A field's values as the file holds them: `source` maps each file component to the memory
// component it comes from, or -1 for a zero pad (vtkComponentSource, shared with particles.vtp).
// Nodes first .. first + n - 1 of the field.
void appendField(std::string& out, const FieldBase& f, std::size_t first, std::size_t n) {
    const std::vector<int> source = vtkComponentSource(f.kind(), f.dimension());
    const std::uint64_t bytes = std::uint64_t(n) * source.size() * 8;
    appendBytes(out, &bytes, sizeof bytes);
    const int components = f.isInteger() ? 1 : f.components();
    bool identity = int(source.size()) == components;
    for (std::size_t k = 0; identity && k < source.size(); ++k) identity = source[k] == int(k);
    // Scalars, integers and 3D vectors and tensors are in the file's layout already: one copy
    // (every value is 8 bytes, an integer field's too).
    const char* base = static_cast<const char*>(f.data()) + first * std::size_t(components) * 8;
    if (identity) return appendBytes(out, base, bytes);
    out.reserve(out.size() + bytes);
    for (std::size_t i = 0; i < n; ++i)
        for (int s : source) {
            // Doubles only: an integer field is one component, always the identity above.
            const double value = s < 0 ? 0.0 : reinterpret_cast<const double*>(base)[i * components + s];
            appendBytes(out, &value, 8);
        }
}

// The node fields named (all of them, in creation order, when `fields` is empty).
std::vector<const FieldBase*> chosenFields(const FieldStore& nodes, const std::vector<std::string>& fields) {
    std::vector<const FieldBase*> chosen;
    if (fields.empty()) {
        for (const auto& f : nodes.fields()) chosen.push_back(f.get());
        return chosen;
    }
    for (const auto& name : fields) {
        const FieldBase* f = nodes.findField(name);
        if (!f) {
            std::string list;
            for (const auto& k : nodes.fieldNames()) list += (list.empty() ? "" : ", ") + k;
            throw Error("grid output: no node field '" + name + "'; the grid has " +
                        (list.empty() ? std::string("none") : list));
        }
        chosen.push_back(f);
    }
    return chosen;
}

// Extent, origin and spacing padded to 3D: the missing axes one node thick, with the first
// axis's spacing (ParaView refuses a zero spacing). The extent's last real axis runs over the
// node layers [firstLayer, lastLayer].
template <int Dim>
std::array<std::string, 3> imageGeometry(const CartesianGrid<Dim>& grid, std::int64_t firstLayer,
                                         std::int64_t lastLayer) {
    std::string extent, origin, spacing;
    for (int d = 0; d < 3; ++d) {
        const bool real = d < Dim;
        const std::int64_t lo = d == Dim - 1 ? firstLayer : 0;
        const std::int64_t hi = d == Dim - 1 ? lastLayer : real ? grid.cells()[d] : 0;
        const char* gap = d ? " " : "";
        extent.append(gap).append(std::to_string(lo)).append(" ").append(std::to_string(hi));
        origin.append(gap).append(number17(real ? grid.origin()[d] : 0.0));
        spacing.append(gap).append(number17(real ? grid.cellSize(d) : grid.cellSize(0)));
    }
    return {extent, origin, spacing};
}

// The .vti of the node layers [firstLayer, lastLayer] along the grid's last axis (all of them:
// the whole image). Nodes are numbered with the first axis fastest, so a run of layers is one
// contiguous run of nodes, and its arrays are that run of the whole image's arrays.
template <int Dim>
std::string imageText(const CartesianGrid<Dim>& grid, double time, const std::vector<std::string>& fields,
                      std::int64_t firstLayer, std::int64_t lastLayer) {
    const std::vector<const FieldBase*> chosen = chosenFields(grid.nodes(), fields);
    std::size_t layerNodes = 1;
    for (int d = 0; d + 1 < Dim; ++d) layerNodes *= std::size_t(grid.cells()[d] + 1);
    const std::size_t first = std::size_t(firstLayer) * layerNodes;
    const std::size_t n = std::size_t(lastLayer - firstLayer + 1) * layerNodes;
    const auto [extent, origin, spacing] = imageGeometry(grid, firstLayer, lastLayer);

    std::ostringstream xml;
    std::uint64_t offset = 0;
    auto array = [&](const std::string& type, const std::string& name, const std::string& count,
                     std::uint64_t bytes) {
        xml << "<DataArray type=\"" << type << "\" Name=\"" << xmlEscape(name) << "\" " << count
            << " format=\"appended\" offset=\"" << offset << "\"/>\n";
        offset += sizeof(std::uint64_t) + bytes;
    };
    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << origin << "\" Spacing=\"" << spacing
        << "\">\n    <FieldData>\n      ";
    array("Int32", "mfdynDimension", "NumberOfTuples=\"1\"", 4);
    xml << "      ";
    array("Float64", "time", "NumberOfTuples=\"1\"", 8);
    xml << "    </FieldData>\n    <Piece Extent=\"" << extent << "\">\n      <PointData>\n";
    for (const FieldBase* f : chosen) {
        xml << "        ";
        const int width = vtkComponents(f->kind());
        array(f->isInteger() ? "Int64" : "Float64", f->name(),
              "NumberOfComponents=\"" + std::to_string(width) + "\"", std::uint64_t(n) * width * 8);
    }
    xml << "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n"
        << "  <AppendedData encoding=\"raw\">\n   _";

    std::string out = xml.str();
    const std::int32_t dim = Dim;
    const std::uint64_t four = 4, eight = 8;
    appendBytes(out, &four, 8);
    appendBytes(out, &dim, 4);
    appendBytes(out, &eight, 8);
    appendBytes(out, &time, 8);
    for (const FieldBase* f : chosen) appendField(out, *f, first, n);
    out += "\n  </AppendedData>\n</VTKFile>\n";
    return out;
}

}  // namespace

std::pair<std::int64_t, std::int64_t> gridSlab(std::int64_t cells, int piece, int pieces) {
    return {cells * piece / pieces, cells * (piece + 1) / pieces};
}

template <int Dim>
int gridPieceCount(const CartesianGrid<Dim>& grid, int ranks) {
    return int(std::min<std::int64_t>(ranks, grid.cells()[Dim - 1]));
}

template <int Dim>
std::string vtiText(const CartesianGrid<Dim>& grid, double time, const std::vector<std::string>& fields) {
    return imageText(grid, time, fields, 0, grid.cells()[Dim - 1]);
}

template <int Dim>
std::string vtiPieceText(const CartesianGrid<Dim>& grid, double time, const std::vector<std::string>& fields,
                         int piece, int pieces) {
    const auto [first, last] = gridSlab(grid.cells()[Dim - 1], piece, pieces);
    return imageText(grid, time, fields, first, last);
}

template <int Dim>
std::string pvtiText(const CartesianGrid<Dim>& grid, const std::vector<std::string>& fields, int pieces,
                     const std::function<std::string(int)>& pieceName) {
    const std::vector<const FieldBase*> chosen = chosenFields(grid.nodes(), fields);
    const auto [whole, origin, spacing] = imageGeometry(grid, 0, grid.cells()[Dim - 1]);
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <PImageData WholeExtent=\"" << whole << "\" GhostLevel=\"0\" Origin=\"" << origin
        << "\" Spacing=\"" << spacing << "\">\n    <PPointData>\n";
    for (const FieldBase* f : chosen)
        xml << "      <PDataArray type=\"" << (f->isInteger() ? "Int64" : "Float64") << "\" Name=\""
            << xmlEscape(f->name()) << "\" NumberOfComponents=\"" << vtkComponents(f->kind()) << "\"/>\n";
    xml << "    </PPointData>\n";
    for (int r = 0; r < pieces; ++r) {
        const auto [first, last] = gridSlab(grid.cells()[Dim - 1], r, pieces);
        xml << "    <Piece Extent=\"" << imageGeometry(grid, first, last)[0] << "\" Source=\""
            << xmlEscape(pieceName(r)) << "\"/>\n";
    }
    xml << "  </PImageData>\n</VTKFile>\n";
    return xml.str();
}

template <int Dim>
ExtraFile vtiFile(const CartesianGrid<Dim>& grid, double time, const std::string& name,
                  const std::vector<std::string>& fields) {
    return {name, vtiText(grid, time, fields)};
}

const VtiImage::Array* VtiImage::find(std::string_view name) const {
    for (const auto& a : arrays)
        if (a.name == name) return &a;
    return nullptr;
}

namespace {

[[noreturn]] void bad(const std::string& fileName, const std::string& what) {
    throw InputError("'" + fileName + "': " + what);
}

const std::string& attribute(const XmlElement& e, std::string_view key, const std::string& fileName) {
    const std::string* value = e.findAttribute(key);
    if (!value)
        bad(fileName, "line " + std::to_string(e.line) + ": <" + e.name + "> has no " + std::string(key));
    return *value;
}

template <class T, std::size_t N>
std::array<T, N> numbers(const std::string& text, const std::string& what, const std::string& fileName) {
    std::array<T, N> out{};
    std::istringstream in(text);
    for (std::size_t k = 0; k < N; ++k)
        if (!(in >> out[k]))
            bad(fileName, what + " \"" + text + "\" does not hold " + std::to_string(N) + " numbers");
    return out;
}

std::uint64_t unsignedNumber(const std::string& text, const std::string& what, const std::string& fileName) {
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        bad(fileName, what + " \"" + text + "\" is not a non-negative integer");
    return value;
}

}  // namespace

VtiImage parseVti(std::string_view text, const std::string& fileName) {
    std::size_t stop = 0;
    const XmlElement root = XmlElement::parse(text, fileName, "AppendedData", &stop);
    if (root.name != "VTKFile" || !root.findAttribute("type") || *root.findAttribute("type") != "ImageData")
        bad(fileName, "not a VTK ImageData (.vti) file");
    if (const std::string* order = root.findAttribute("byte_order"); !order || *order != "LittleEndian")
        bad(fileName, "only LittleEndian files are read");
    if (const std::string* header = root.findAttribute("header_type"); !header || *header != "UInt64")
        bad(fileName, "only header_type UInt64 is read");
    const XmlElement* image = root.findChild("ImageData");
    const XmlElement* appended = root.findChild("AppendedData");
    if (!image || !appended) bad(fileName, "no <ImageData> or no <AppendedData> element");
    if (const std::string* enc = appended->findAttribute("encoding"); !enc || *enc != "raw")
        bad(fileName, "only raw appended data is read");
    while (stop < text.size() && std::isspace(static_cast<unsigned char>(text[stop]))) ++stop;
    if (stop >= text.size() || text[stop] != '_') bad(fileName, "no '_' starting the appended data");
    const std::size_t dataStart = stop + 1;

    VtiImage out;
    const auto extent =
        numbers<std::int64_t, 6>(attribute(*image, "WholeExtent", fileName), "WholeExtent", fileName);
    out.origin = numbers<double, 3>(attribute(*image, "Origin", fileName), "Origin", fileName);
    out.spacing = numbers<double, 3>(attribute(*image, "Spacing", fileName), "Spacing", fileName);
    std::uint64_t points = 1;
    for (int d = 0; d < 3; ++d) {
        if (extent[2 * d] < 0 || extent[2 * d + 1] < extent[2 * d])
            bad(fileName, "WholeExtent must be a0 b0 a1 b1 a2 b2 with 0 <= a <= b");
        out.first[d] = extent[2 * d];
        out.cells[d] = extent[2 * d + 1];
        points *= std::uint64_t(out.cells[d] - out.first[d] + 1);
    }

    // The bytes of the array at `offset` in the appended data, checked against its stated size.
    auto block = [&](const XmlElement& e, std::uint64_t expected) {
        if (const std::string* format = e.findAttribute("format"); !format || *format != "appended")
            bad(fileName, "line " + std::to_string(e.line) + ": only appended arrays are read");
        const std::uint64_t offset = unsignedNumber(attribute(e, "offset", fileName), "offset", fileName);
        if (offset > text.size() || dataStart + offset + 8 > text.size())
            bad(fileName, "truncated: array at line " + std::to_string(e.line) + " lies beyond the end");
        std::uint64_t bytes = 0;
        std::memcpy(&bytes, text.data() + dataStart + offset, 8);
        if (bytes != expected || dataStart + offset + 8 + bytes > text.size())
            bad(fileName, "array at line " + std::to_string(e.line) + " holds " + std::to_string(bytes) +
                              " bytes, expected " + std::to_string(expected));
        return text.data() + dataStart + offset + 8;
    };

    bool hasDimension = false;
    if (const XmlElement* fieldData = image->findChild("FieldData")) {
        for (const XmlElement* e : fieldData->childrenNamed("DataArray")) {
            const std::string& name = attribute(*e, "Name", fileName);
            if (name == "mfdynDimension") {
                std::int32_t dim = 0;
                std::memcpy(&dim, block(*e, 4), 4);
                out.dimension = dim;
                hasDimension = true;
            } else if (name == "time") {
                std::memcpy(&out.time, block(*e, 8), 8);
            }
        }
    }
    if (!hasDimension || out.dimension < 1 || out.dimension > 3)
        bad(fileName, "no mfdynDimension of 1, 2 or 3 in its FieldData");

    const XmlElement* piece = image->findChild("Piece");
    if (!piece) bad(fileName, "no <Piece>");
    if (const XmlElement* pointData = piece->findChild("PointData")) {
        for (const XmlElement* e : pointData->childrenNamed("DataArray")) {
            VtiImage::Array a;
            a.name = attribute(*e, "Name", fileName);
            a.type = attribute(*e, "type", fileName);
            if (a.type != "Float64" && a.type != "Int64")
                bad(fileName, "array '" + a.name + "' is " + a.type + "; only Float64 and Int64 are read");
            a.components = int(unsignedNumber(attribute(*e, "NumberOfComponents", fileName),
                                              "NumberOfComponents", fileName));
            if (a.components < 1 || a.components > 9)
                bad(fileName, "array '" + a.name + "' has " + std::to_string(a.components) + " components");
            const std::size_t count = std::size_t(points) * std::size_t(a.components);
            const char* bytes = block(*e, std::uint64_t(count) * 8);
            a.values.resize(count);
            for (std::size_t k = 0; k < count; ++k) {
                if (a.type == "Float64") {
                    std::memcpy(&a.values[k], bytes + 8 * k, 8);
                } else {
                    std::int64_t v = 0;
                    std::memcpy(&v, bytes + 8 * k, 8);
                    a.values[k] = double(v);
                }
            }
            out.arrays.push_back(std::move(a));
        }
    }
    return out;
}

template std::string vtiText<1>(const CartesianGrid<1>&, double, const std::vector<std::string>&);
template std::string vtiText<2>(const CartesianGrid<2>&, double, const std::vector<std::string>&);
template std::string vtiText<3>(const CartesianGrid<3>&, double, const std::vector<std::string>&);
#define MFDYN_GRID_PIECES(D)                                                                               \
    template int gridPieceCount<D>(const CartesianGrid<D>&, int);                                          \
    template std::string vtiPieceText<D>(const CartesianGrid<D>&, double, const std::vector<std::string>&, \
                                         int, int);                                                        \
    template std::string pvtiText<D>(const CartesianGrid<D>&, const std::vector<std::string>&, int,        \
                                     const std::function<std::string(int)>&);
MFDYN_GRID_PIECES(1)
MFDYN_GRID_PIECES(2)
MFDYN_GRID_PIECES(3)
#undef MFDYN_GRID_PIECES
template ExtraFile vtiFile<1>(const CartesianGrid<1>&, double, const std::string&,
                              const std::vector<std::string>&);
template ExtraFile vtiFile<2>(const CartesianGrid<2>&, double, const std::string&,
                              const std::vector<std::string>&);
template ExtraFile vtiFile<3>(const CartesianGrid<3>&, double, const std::string&,
                              const std::vector<std::string>&);

}  // namespace mfdyn
