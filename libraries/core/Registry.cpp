#include "core/Registry.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace mfdyn {

const RegistryItem* RegistryFamily::find(std::string_view type, std::string_view signature) const {
    for (const auto& item : items)
        if (item.name == type && (signature.empty() || item.signature == signature)) return &item;
    return nullptr;
}

std::vector<std::string> RegistryFamily::names() const {
    std::vector<std::string> out;
    for (const auto& item : items)
        if (out.empty() || out.back() != item.name) out.push_back(item.name);
    return out;
}

std::string RegistryFamily::unknownTypeMessage(std::string_view type) const {
    std::ostringstream s;
    s << "unknown " << name << " type '" << type << "'";
    if (auto guess = closestMatch(type, names()); !guess.empty()) s << "; did you mean '" << guess << "'?";
    return s.str() + validTypes();
}

std::string RegistryFamily::validTypes() const {
    std::ostringstream s;
    if (items.empty()) {
        s << "\n    no " << name
          << " types are registered (is the library that provides them loaded with libs (...)?)";
    } else {
        s << "\n    valid " << name << " types:";
        for (std::size_t k = 0; k < items.size(); ++k)
            if (k == 0 || items[k].name != items[k - 1].name)
                s << "\n        " << items[k].name << "  (" << items[k].library << ")";
    }
    return s.str();
}

RegistryIndex& RegistryIndex::global() {
    static RegistryIndex index;
    return index;
}

RegistryFamily& RegistryIndex::family(std::string_view name) {
    for (auto& f : families_)
        if (f->name == name) return *f;
    families_.push_back(std::make_unique<RegistryFamily>());
    families_.back()->name = std::string(name);
    return *families_.back();
}

const RegistryFamily* RegistryIndex::findFamily(std::string_view name) const {
    for (const auto& f : families_)
        if (f->name == name) return f.get();
    return nullptr;
}

std::vector<const RegistryFamily*> RegistryIndex::families() const {
    std::vector<const RegistryFamily*> out;
    for (const auto& f : families_) out.push_back(f.get());
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->name < b->name; });
    return out;
}

void RegistryIndex::add(std::string_view familyName, RegistryItem item) {
    RegistryFamily& fam = family(familyName);
    if (const RegistryItem* existing = fam.find(item.name, item.signature)) {
        // Static initialisers cannot throw usefully: remember the clash and report it before
        // anything is selected (checkConflicts).
        fam.conflicts.push_back(fam.name + " type '" + item.name + "' is registered twice: by " +
                                existing->library + " and by " + item.library);
        return;
    }
    auto pos = std::upper_bound(fam.items.begin(), fam.items.end(), item.name,
                                [](const std::string& n, const RegistryItem& a) { return n < a.name; });
    fam.items.insert(pos, std::move(item));
}

void RegistryIndex::checkConflicts() const {
    std::string all;
    for (const auto& f : families_)
        for (const auto& c : f->conflicts) all += (all.empty() ? "" : "\n") + c;
    if (!all.empty()) throw Error(all);
}

namespace {

// The items of `fam` one per name (the first dimension of a Dim-templated family).
std::vector<const RegistryItem*> distinctItems(const RegistryFamily& fam) {
    std::vector<const RegistryItem*> out;
    for (const auto& item : fam.items)
        if (out.empty() || out.back()->name != item.name) out.push_back(&item);
    return out;
}

std::string familyListing(const RegistryFamily& fam) {
    std::ostringstream s;
    s << fam.name << "\n";
    std::size_t width = 0;
    for (const auto& item : fam.items) width = std::max(width, item.name.size());
    for (const RegistryItem* item : distinctItems(fam)) {
        s << "    " << item->name << std::string(width + 2 - item->name.size(), ' ') << item->description;
        if (item->library.rfind("libmfdyn_", 0) != 0) s << "  [" << item->library << "]";
        s << "\n";
        if (item->keywords) s << item->keywords().summary("        ");
    }
    return s.str();
}

std::string typeDescription(const RegistryFamily& fam, const RegistryItem& item) {
    std::ostringstream s;
    s << fam.name << " " << item.name << ": " << item.description << "\n";
    s << "    library: " << item.library << "\n";
    if (!item.sourceFile.empty()) s << "    source:  " << item.sourceFile << "\n";
    std::string dims;
    for (const auto& other : fam.items)
        if (other.name == item.name && other.dimension > 0)
            dims += (dims.empty() ? "" : ", ") + std::to_string(other.dimension) + "D";
    if (!dims.empty()) s << "    dimensions: " << dims << "\n";
    if (!item.keywords) {
        s << "    keywords: no schema declared yet (see the source file)\n";
        return s.str();
    }
    const KeywordSchema schema = item.keywords();
    s << "    keywords:\n";
    for (const Keyword& k : schema.keywords()) {
        s << "        " << k.name << "  [" << k.unit << "]  " << k.kindText() << "  " << k.typeText();
        if (const std::string b = k.boundsText(); !b.empty()) s << ", " << b;
        s << "\n            " << k.meaning;
        if (k.orEnclosing) s << " (here or in the enclosing dictionary)";
        s << "\n";
    }
    return s.str();
}

}  // namespace

std::string RegistryIndex::listing() const {
    std::string s;
    for (const RegistryFamily* fam : families()) s += familyListing(*fam);
    return s;
}

std::string RegistryIndex::describe(std::string_view what) const {
    const std::size_t cut = what.find('/');
    const std::string_view familyPart =
        cut == std::string_view::npos ? std::string_view{} : what.substr(0, cut);
    const std::string_view typePart = cut == std::string_view::npos ? what : what.substr(cut + 1);
    if (familyPart.empty())
        if (const RegistryFamily* fam = findFamily(what)) return familyListing(*fam);
    std::string s;
    std::vector<std::string> all;
    for (const RegistryFamily* fam : families()) {
        all.push_back(fam->name);
        if (!familyPart.empty() && fam->name != familyPart) continue;
        for (const RegistryItem* item : distinctItems(*fam)) {
            all.push_back(item->name);
            if (item->name == typePart) s += (s.empty() ? "" : "\n") + typeDescription(*fam, *item);
        }
    }
    if (!s.empty()) return s;
    std::string message = "-describe: no model family or type '" + std::string(what) + "'";
    if (auto guess = closestMatch(typePart, all); !guess.empty())
        message += "; did you mean '" + guess + "'?";
    message += "\n    families:";
    for (const RegistryFamily* fam : families()) message += " " + fam->name;
    throw InputError(message);
}

std::string sourceFileRelative(const char* file) {
    if (!file || !*file) return {};
    const std::filesystem::path path = std::filesystem::path(file).lexically_normal();
#ifdef MFDYN_SOURCE_DIR
    const std::filesystem::path root = std::filesystem::path(MFDYN_SOURCE_DIR).lexically_normal();
    const std::filesystem::path relative = path.lexically_relative(root);
    if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
#endif
    return path.generic_string();
}

std::string sharedObjectOf(const void* address) {
    Dl_info info{};
    if (dladdr(address, &info) && info.dli_fname && *info.dli_fname)
        return std::filesystem::path(info.dli_fname).filename().string();
    return "program";
}

}  // namespace mfdyn
