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
        s << "\n    no " << name << " types are registered (is the library that provides them loaded with libs (...)?)";
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

std::string RegistryIndex::listing() const {
    std::ostringstream s;
    for (const RegistryFamily* fam : families()) {
        s << fam->name << "\n";
        std::size_t width = 0;
        for (const auto& item : fam->items) width = std::max(width, item.name.size());
        for (std::size_t k = 0; k < fam->items.size(); ++k) {
            const RegistryItem& item = fam->items[k];
            if (k > 0 && fam->items[k - 1].name == item.name) continue;  // one line for all dimensions
            s << "    " << item.name << std::string(width + 2 - item.name.size(), ' ') << item.description;
            if (item.library.rfind("libmfdyn_", 0) != 0) s << "  [" << item.library << "]";
            s << "\n";
        }
    }
    return s.str();
}

std::string sharedObjectOf(const void* address) {
    Dl_info info{};
    if (dladdr(address, &info) && info.dli_fname && *info.dli_fname)
        return std::filesystem::path(info.dli_fname).filename().string();
    return "program";
}

}  // namespace mfdyn
