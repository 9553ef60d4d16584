#include "grid/VtiWriter.hpp"

#include "core/Error.hpp"
#include "particles/VtpWriter.hpp"
#include "particles/XmlElement.hpp"

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
void appendField(std::string& out, const FieldBase& f, std::size_t n) {
    const std::vector<int> source = vtkComponentSource(f.kind(), f.dimension());
    const std::uint64_t bytes = std::uint64_t(n) * source.size() * 8;
    appendBytes(out, &bytes, sizeof bytes);
    const int components = f.isInteger() ? 1 : f.components();
    bool identity = int(source.size()) == components;
    for (std::size_t k = 0; identity && k < source.size(); ++k) identity = source[k] == int(k);
    // Scalars, integers and 3D vectors and tensors are in the file's layout already: one copy.
    if (identity) return appendBytes(out, f.data(), bytes);
    out.reserve(out.size() + bytes);
    for (std::size_t i = 0; i < n; ++i)
        for (int s : source) {
            // Doubles only: an integer field is one component, always the identity above.
            const double value = s < 0 ? 0.0 : static_cast<const double*>(f.data())[i * components + s];
            appendBytes(out, &value, 8);
        }
}

}  // namespace

template <int Dim>
std::string vtiText(const CartesianGrid<Dim>& grid, double time, const std::vector<std::string>& fields) {
    const FieldStore& nodes = grid.nodes();
    std::vector<const FieldBase*> chosen;
    if (fields.empty()) {
        for (const auto& f : nodes.fields()) chosen.push_back(f.get());
    } else {
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
    }

    const std::size_t n = grid.nodeCount();
    // Extent, origin and spacing padded to 3D: the missing axes one node thick, with the first
    // axis's spacing (ParaView refuses a zero spacing).
    std::string extent, origin, spacing;
    for (int d = 0; d < 3; ++d) {
        const bool real = d < Dim;
        extent += std::string(d ? " " : "") + "0 " + std::to_string(real ? grid.cells()[d] : 0);
        origin += (d ? " " : "") + number17(real ? grid.origin()[d] : 0.0);
        spacing += (d ? " " : "") + number17(real ? grid.cellSize(d) : grid.cellSize(0));
    }

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
    for (const FieldBase* f : chosen) appendField(out, *f, n);
    out += "\n  </AppendedData>\n</VTKFile>\n";
    return out;
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
        if (extent[2 * d] != 0 || extent[2 * d + 1] < 0) bad(fileName, "WholeExtent must be 0 n0 0 n1 0 n2");
        out.cells[d] = extent[2 * d + 1];
        points *= std::uint64_t(out.cells[d] + 1);
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
template ExtraFile vtiFile<1>(const CartesianGrid<1>&, double, const std::string&,
                              const std::vector<std::string>&);
template ExtraFile vtiFile<2>(const CartesianGrid<2>&, double, const std::string&,
                              const std::vector<std::string>&);
template ExtraFile vtiFile<3>(const CartesianGrid<3>&, double, const std::string&,
                              const std::vector<std::string>&);

}  // namespace mfdyn
