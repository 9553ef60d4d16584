#include "core/Registry.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <tuple>

namespace mfdyn {

std::string RegistryFamily::title() const {
    return method.empty() ? name : name + " (" + method + ")";
}

std::string RegistryFamily::key() const {
    return method.empty() ? name : method + "/" + name;
}

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
    s << "unknown " << title() << " type '" << type << "'";
    if (auto guess = closestMatch(type, names()); !guess.empty()) s << "; did you mean '" << guess << "'?";
    return s.str() + validTypes();
}

std::string RegistryFamily::validTypes() const {
    std::ostringstream s;
    if (items.empty()) {
        s << "\n    no " << title()
          << " types are registered (is the library that provides them loaded with libs (...)?)";
    } else {
        s << "\n    valid " << title() << " types:";
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

RegistryFamily& RegistryIndex::family(std::string_view name, std::string_view method) {
    for (auto& f : families_)
        if (f->name == name && f->method == method) return *f;
    families_.push_back(std::make_unique<RegistryFamily>());
    families_.back()->name = std::string(name);
    families_.back()->method = std::string(method);
    return *families_.back();
}

const RegistryFamily* RegistryIndex::findFamily(std::string_view name, std::string_view method) const {
    for (const auto& f : families_)
        if (f->name == name && f->method == method) return f.get();
    return nullptr;
}

std::vector<const RegistryFamily*> RegistryIndex::familiesNamed(std::string_view name) const {
    std::vector<const RegistryFamily*> out;
    for (const RegistryFamily* f : families())
        if (f->name == name) out.push_back(f);
    return out;
}

std::vector<const RegistryFamily*> RegistryIndex::families() const {
    std::vector<const RegistryFamily*> out;
    for (const auto& f : families_) out.push_back(f.get());
    std::sort(out.begin(), out.end(),
              [](auto* a, auto* b) { return std::tie(a->name, a->method) < std::tie(b->name, b->method); });
    return out;
}

void RegistryIndex::add(std::string_view familyName, RegistryItem item, std::string_view method) {
    RegistryFamily& fam = family(familyName, method);
    if (const RegistryItem* existing = fam.find(item.name, item.signature)) {
        // Static initialisers cannot throw usefully: remember the clash and report it before
        // anything is selected (checkConflicts).
        fam.conflicts.push_back(fam.title() + " type '" + item.name + "' is registered twice: by " +
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

// `shownAbove`: a type whose keywords the listing has already given (the application's solver).
std::string familyListing(const RegistryFamily& fam, std::string_view shownAbove = {}) {
    std::ostringstream s;
    s << fam.title() << "\n";
    std::size_t width = 0;
    for (const auto& item : fam.items) width = std::max(width, item.name.size());
    for (const RegistryItem* item : distinctItems(fam)) {
        s << "    " << item->name << std::string(width + 2 - item->name.size(), ' ') << item->description;
        if (item->library.rfind("libmfdyn_", 0) != 0) s << "  [" << item->library << "]";
        s << "\n";
        if (item->keywords && item->name == shownAbove)
            s << "        (its keywords are listed first, above)\n";
        else if (item->keywords)
            s << item->keywords().summary("        ");
    }
    return s.str();
}

// Every keyword of `schema` with its meaning; a sub-dictionary's nested keywords indented below it.
std::string keywordDescriptions(const KeywordSchema& schema, const std::string& indent) {
    std::ostringstream s;
    for (const Keyword& k : schema.keywords()) {
        s << indent << k.name << "  [" << k.unit << "]  " << k.kindText() << "  " << k.typeText();
        if (const std::string b = k.boundsText(); !b.empty()) s << ", " << b;
        s << "\n" << indent << "    " << k.meaning;
        if (k.orEnclosing) s << " (here or in the enclosing dictionary)";
        s << "\n";
        if (k.nested) s << keywordDescriptions(k.nested(), indent + "    ");
    }
    return s.str();
}

std::string typeDescription(const RegistryFamily& fam, const RegistryItem& item) {
    std::ostringstream s;
    s << fam.title() << " " << item.name << ": " << item.description << "\n";
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
    if (!item.dictionary.empty()) s << "    dictionary: constant/" << item.dictionary << "\n";
    s << "    keywords:\n";
    s << keywordDescriptions(item.keywords(), "        ");
    return s.str();
}

}  // namespace

std::string RegistryIndex::listing(std::string_view solver) const {
    std::string s;
    const RegistryFamily* solvers = findFamily("solver");
    const RegistryItem* first = solvers && !solver.empty() ? solvers->find(solver) : nullptr;
    if (first) {
        s += "solver " + first->name + ": " + first->description + "\n";
        s += "    keywords of " +
             (first->dictionary.empty() ? std::string("its properties dictionary")
                                        : "constant/" + first->dictionary) +
             ":\n";
        s += first->keywords ? first->keywords().summary("        ") : "        (no schema declared yet)\n";
        s += "\n";
    }
    for (const RegistryFamily* fam : families())
        s += familyListing(*fam, first && fam == solvers ? solver : std::string_view{});
    return s;
}

std::string RegistryIndex::describe(std::string_view what) const {
    // Split "a/b/c" into its parts: a family or type; family/type or method/family;
    // method/family/type.
    std::vector<std::string_view> parts;
    for (std::size_t begin = 0;;) {
        const std::size_t cut = what.find('/', begin);
        parts.push_back(what.substr(begin, cut == std::string_view::npos ? cut : cut - begin));
        if (cut == std::string_view::npos) break;
        begin = cut + 1;
    }
    const auto join = [](const std::vector<const RegistryFamily*>& fams) {
        std::string s;
        for (const RegistryFamily* fam : fams) s += (s.empty() ? "" : "\n") + familyListing(*fam);
        return s;
    };
    // The families a type is looked for in, and the type's name.
    std::vector<const RegistryFamily*> scope;
    std::string_view typePart;
    if (parts.size() == 1) {
        if (auto named = familiesNamed(what); !named.empty()) return join(named);
        scope = families();
        typePart = what;
    } else if (parts.size() == 2) {
        if (const RegistryFamily* fam = findFamily(parts[1], parts[0])) return familyListing(*fam);
        scope = familiesNamed(parts[0]);
        typePart = parts[1];
    } else if (parts.size() == 3) {
        if (const RegistryFamily* fam = findFamily(parts[1], parts[0])) scope.push_back(fam);
        typePart = parts[2];
    }
    std::string s;
    for (const RegistryFamily* fam : scope)
        for (const RegistryItem* item : distinctItems(*fam))
            if (item->name == typePart) {
                s += (s.empty() ? "" : "\n") + typeDescription(*fam, *item);
                if (fam->name != "solver" || !fam->method.empty()) continue;
                // A solver: the families that belong to its method.
                std::string own;
                for (const RegistryFamily* other : families())
                    if (other->method == item->name) own += " " + other->key();
                if (!own.empty())
                    s += "    families of this method (-describe <method>/<family>):" + own + "\n";
            }
    if (!s.empty()) return s;
    std::vector<std::string> all;
    for (const RegistryFamily* fam : families()) {
        all.push_back(fam->name);
        all.push_back(fam->key());
        for (const RegistryItem* item : distinctItems(*fam)) {
            all.push_back(item->name);
            all.push_back(fam->key() + "/" + item->name);
        }
    }
    std::string message = "-describe: no model family or type '" + std::string(what) + "'";
    if (auto guess = closestMatch(what, all); !guess.empty()) message += "; did you mean '" + guess + "'?";
    message += "\n    families:";
    for (const RegistryFamily* fam : families()) message += " " + fam->key();
    throw InputError(message);
}

std::string sourceFileRelative(const char* file) {
    if (!file || !*file) return {};
    std::filesystem::path path = std::filesystem::path(file).lexically_normal();
    if (path.is_relative()) {
        // A relative __FILE__ is relative to the compiler's directory, somewhere in the build
        // tree (ccache's base_dir rewrites the paths so, for one): what follows its leading ".."
        // is the path in the source tree ("../libraries/core/Registry.cpp" from build/ under
        // Ninja, "../../../libraries/..." from a Makefile build's subdirectory).
        std::filesystem::path rest;
        bool leading = true;
        for (const auto& part : path) {
            if (leading && (part == ".." || part == ".")) continue;
            leading = false;
            rest /= part;
        }
        return rest.generic_string();
    }
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
