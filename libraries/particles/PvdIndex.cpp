#include "particles/PvdIndex.hpp"

#include "core/Error.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/XmlElement.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace mfdyn {

PvdIndex::PvdIndex(std::filesystem::path file) : file_(std::move(file)) {}

PvdIndex PvdIndex::read(const std::filesystem::path& file) {
    PvdIndex index(file);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return index;
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw InputError("cannot read '" + file.string() + "'");
    const XmlElement root = XmlElement::parse(text.str(), file.string());
    const XmlElement* collection = root.findChild("Collection");
    if (root.name != "VTKFile" || !collection)
        throw InputError("'" + file.string() + "' is not a VTK collection (.pvd) file");
    for (const XmlElement* e : collection->childrenNamed("DataSet")) {
        const std::string* time = e->findAttribute("timestep");
        const std::string* name = e->findAttribute("file");
        double value = 0;
        if (!time || !name ||
            std::from_chars(time->data(), time->data() + time->size(), value).ptr !=
                time->data() + time->size())
            throw InputError("'" + file.string() + "' line " + std::to_string(e->line) +
                             ": DataSet needs a numeric timestep and a file");
        index.add(value, *name);
    }
    return index;
}

void PvdIndex::truncateAfter(double time) {
    std::erase_if(entries_, [time](const Entry& e) { return e.time > time; });
}

void PvdIndex::add(double time, const std::string& file) {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), time,
                               [](const Entry& e, double t) { return e.time < t; });
    if (it != entries_.end() && it->time == time)
        it->file = file;
    else
        entries_.insert(it, Entry{time, file});
}

void PvdIndex::write() const {
    std::string s =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        "  <Collection>\n";
    for (const Entry& e : entries_) {
        // 17 significant digits: a re-read time compares equal to the one written.
        char time[32];
        std::snprintf(time, sizeof time, "%.17g", e.time);
        s += "    <DataSet timestep=\"" + std::string(time) + "\" part=\"0\" file=\"" + xmlEscape(e.file) +
             "\"/>\n";
    }
    s += "  </Collection>\n</VTKFile>\n";
    writeFileAtomically(file_, s);
}

}  // namespace mfdyn
