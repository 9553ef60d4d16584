#include "particles/PvdIndex.hpp"

#include "core/Error.hpp"
#include "particles/RegularFile.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/XmlElement.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace mfdyn {

PvdIndex::PvdIndex(std::filesystem::path file) : file_(std::move(file)) {}

PvdIndex PvdIndex::read(const std::filesystem::path& file) {
    PvdIndex index(file);
    std::error_code ec;
    // symlink_status: a dangling link is "there" and an error below, not an empty index that
    // the next write would put in its place.
    if (std::filesystem::symlink_status(file, ec).type() == std::filesystem::file_type::not_found)
        return index;
    const RegularFile text(file);  // a FIFO or directory is an InputError, not a wait
    const XmlElement root = XmlElement::parse(text.view(), file.string());
    const XmlElement* collection = root.findChild("Collection");
    if (root.name != "VTKFile" || !collection)
        throw InputError("'" + file.string() + "' is not a VTK collection (.pvd) file");
    const auto dataSets = collection->childrenNamed("DataSet");
    index.entries_.reserve(dataSets.size());
    for (const XmlElement* e : dataSets) {
        const std::string* time = e->findAttribute("timestep");
        const std::string* name = e->findAttribute("file");
        const std::string* partText = e->findAttribute("part");
        int part = 0;
        if (partText && (std::from_chars(partText->data(), partText->data() + partText->size(), part).ptr !=
                             partText->data() + partText->size() ||
                         part < 0))
            throw InputError("'" + file.string() + "' line " + std::to_string(e->line) + ": part \"" +
                             *partText + "\" is not a non-negative integer");
        double value = 0;
        if (!time || !name ||
            std::from_chars(time->data(), time->data() + time->size(), value).ptr !=
                time->data() + time->size())
            throw InputError("'" + file.string() + "' line " + std::to_string(e->line) +
                             ": DataSet needs a numeric timestep and a file");
        // from_chars reads "nan" and "inf" too; neither is a time, and a NaN would break the
        // ordering that add() and truncateAfter() rely on.
        if (!std::isfinite(value))
            throw InputError("'" + file.string() + "' line " + std::to_string(e->line) + ": timestep \"" +
                             *time + "\" is not a finite number");
        index.entries_.push_back(Entry{value, *name, part});
    }
    // What add() one at a time would give (sorted by time and part, the last entry of a time
    // and part kept), in n log n: add() inserts into a vector, quadratic for an index listed in
    // reverse.
    std::stable_sort(index.entries_.begin(), index.entries_.end(), [](const Entry& a, const Entry& b) {
        return a.time < b.time || (a.time == b.time && a.part < b.part);
    });
    std::vector<Entry> unique;
    unique.reserve(index.entries_.size());
    for (Entry& e : index.entries_) {
        if (!unique.empty() && unique.back().time == e.time && unique.back().part == e.part)
            unique.back() = std::move(e);
        else
            unique.push_back(std::move(e));
    }
    index.entries_ = std::move(unique);
    return index;
}

void PvdIndex::truncateAfter(double time) {
    std::erase_if(entries_, [time](const Entry& e) { return e.time > time; });
}

void PvdIndex::add(double time, const std::string& file, int part) {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair(time, part),
                               [](const Entry& e, const std::pair<double, int>& key) {
                                   return e.time < key.first || (e.time == key.first && e.part < key.second);
                               });
    if (it != entries_.end() && it->time == time && it->part == part)
        it->file = file;
    else
        entries_.insert(it, Entry{time, file, part});
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
        s += "    <DataSet timestep=\"" + std::string(time) + "\" part=\"" + std::to_string(e.part) +
             "\" file=\"" + xmlEscape(e.file) + "\"/>\n";
    }
    s += "  </Collection>\n</VTKFile>\n";
    writeFileAtomically(file_, s);
}

}  // namespace mfdyn
