// mfDictionary: print a dictionary with its includes and macros expanded, print one entry, list
// keywords, or set an entry's value in the file itself. Editing splices the new text into the
// entry's byte span and leaves every other byte (comments, layout) as it was, then re-parses the
// result before replacing the file, so a bad value never reaches the disk.
#include "core/Application.hpp"
#include "core/Dictionary.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace mfdyn;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot open file '" + path.string() + "'");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeAtomically(const fs::path& path, const std::string& text) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot write '" + tmp.string() + "'");
        out << text;
        out.flush();
        if (!out) throw Error("cannot write '" + tmp.string() + "'");
    }
    std::error_code ec;
    fs::permissions(tmp, fs::status(path).permissions(), ec);
    fs::rename(tmp, path);
}

std::vector<std::string> splitPath(const std::string& scoped) {
    std::vector<std::string> parts;
    std::string part;
    for (char c : scoped) {
        if (c == '/') {
            if (!part.empty()) parts.push_back(part);
            part.clear();
        } else {
            part += c;
        }
    }
    if (!part.empty()) parts.push_back(part);
    if (parts.empty()) throw InputError("empty entry name '" + scoped + "'");
    return parts;
}

std::string valueText(const Entry& e) {
    if (e.isDict()) return e.dict->str();
    std::string s;
    for (const Token& t : e.tokens) s += (s.empty() ? "" : " ") + t.str();
    return s + "\n";
}

bool startsDict(const std::string& value) {
    const auto b = value.find_first_not_of(" \t\r\n");
    return b != std::string::npos && value[b] == '{';
}

// The entry of `scope` that `path[depth..]` starts with, as (entry, components used). A key may
// itself contain '/' (a studyDict's `system/controlDict/deltaT 0.04;`): the longest run of
// components that names a key wins, so that `resolution/scale/system/controlDict/deltaT` reaches
// it instead of looking for a dictionary `system` in `scale`.
std::pair<const Entry*, std::size_t> lookUp(const Dictionary& scope, const std::vector<std::string>& path,
                                            std::size_t depth) {
    for (std::size_t n = path.size() - depth; n >= 1; --n) {
        std::string key = path[depth];
        for (std::size_t k = 1; k < n; ++k) key += "/" + path[depth + k];
        if (const Entry* e = scope.peek(key)) return {e, n};
    }
    return {nullptr, 0};
}

// When `path[depth]` names nothing in `scope` but keys there contain '/' and begin with it, the
// entry asked for is one of them spelt otherwise (or a new one): adding nested dictionaries
// `path[depth] { ... }` beside them would be a silent mistake. An InputError listing them.
void refuseNestedBesideSlashKeys(const Dictionary& scope, const std::vector<std::string>& path,
                                 std::size_t depth, const std::string& scoped) {
    std::string similar;
    for (const auto& key : scope.keys())
        if (key.rfind(path[depth] + "/", 0) == 0) similar += (similar.empty() ? "" : " | ") + key;
    if (similar.empty() || depth + 1 == path.size()) return;
    throw InputError(
        scope.where(), scope.scope(),
        "no entry '" + scoped +
            "': " + (scope.scope().empty() ? std::string("the top level") : "'" + scope.scope() + "'") +
            " has no '" + path[depth] + "', and its keys that contain '/' and begin with it are: " + similar +
            " (name one of them whole after the dictionaries that hold it; a new "
            "nested dictionary '" +
            path[depth] + "' is not made beside them)");
}

// The entry `scoped` names, keys containing '/' included (lookUp); null when there is none.
const Entry* findEntry(const Dictionary& dict, const std::string& scoped) {
    const auto path = splitPath(scoped);
    const Dictionary* scope = &dict;
    for (std::size_t depth = 0; depth < path.size();) {
        const auto [e, used] = lookUp(*scope, path, depth);
        if (!e) {
            refuseNestedBesideSlashKeys(*scope, path, depth, scoped);
            return nullptr;
        }
        depth += used;
        if (depth == path.size()) return e;
        if (!e->isDict()) return nullptr;
        scope = e->dict.get();
    }
    return nullptr;
}

// The text of `path[from..]` set to `value`, nested in new sub-dictionaries, indented for `depth`.
std::string newEntriesText(const std::vector<std::string>& path, std::size_t from, const std::string& value) {
    std::string text;
    const auto pad = [](std::size_t depth) { return std::string(4 * depth, ' '); };
    for (std::size_t i = from; i + 1 < path.size(); ++i) text += pad(i) + path[i] + "\n" + pad(i) + "{\n";
    text += pad(path.size() - 1) + path.back() + " " + value + (startsDict(value) ? "\n" : ";\n");
    for (std::size_t i = path.size() - 1; i-- > from;) text += pad(i) + "}\n";
    return text;
}

// The file's text with `scoped` set to `value`.
std::string edit(const std::string& text, const std::string& fileName, const std::string& scoped,
                 const std::string& value) {
    const Dictionary dict = Dictionary::parse(text, fileName);
    const auto path = splitPath(scoped);
    const Dictionary* scope = &dict;
    std::size_t depth = 0;
    const Entry* found = nullptr;
    std::vector<std::string> keys;  // the keys of the dictionaries passed through, one per level
    while (depth < path.size()) {
        const auto [e, used] = lookUp(*scope, path, depth);
        if (!e) {
            refuseNestedBesideSlashKeys(*scope, path, depth, scoped);
            break;
        }
        if (depth + used == path.size()) {
            found = e;
            keys.push_back(e->key);
            break;
        }
        if (!e->isDict())
            throw InputError(
                e->where, scope->scope(),
                "'" + path[depth] + "' is not a dictionary, cannot set '" + scoped + "' inside it");
        scope = e->dict.get();
        keys.push_back(e->key);
        depth += used;
    }

    // An entry written in this file is replaced where it stands; one that came from an include
    // or a macro is overridden by a new entry in this file, as a user would do by hand.
    if (found && !found->fromInclude && found->where.file && *found->where.file == fileName) {
        std::size_t begin = found->valueBegin, end = found->valueEnd;
        std::string replacement = value;
        if (found->isDict()) {
            --begin;  // the braces too
            ++end;
            if (!startsDict(value)) replacement += ";";
        } else if (begin == end && begin > 0 && text[begin - 1] != ' ' && text[begin - 1] != '\t') {
            replacement = " " + replacement;
        }
        return text.substr(0, begin) + replacement + text.substr(end);
    }

    // What to write: the found key (from an include, overridden here) or the rest of the path,
    // each component a new nested dictionary, from the level reached.
    std::size_t level = keys.size();
    if (found)
        level = keys.size() - 1;
    else
        keys.insert(keys.end(), path.begin() + long(depth), path.end());
    if (!scope->where().file || *scope->where().file != fileName || scope->closeBraceOffset > text.size())
        throw InputError(scope->where(), scope->scope(),
                         "cannot add '" + scoped + "': its dictionary is not written out in " + fileName);
    std::size_t at = scope->closeBraceOffset;
    const std::string insertion = newEntriesText(keys, level, value);
    if (at == text.size()) {  // top level: append at the end of the file
        std::string result = text;
        if (!result.empty() && result.back() != '\n') result += '\n';
        return result + insertion;
    }
    // Before the closing brace, on a line of its own when the brace has one.
    std::size_t lineStart = at;
    while (lineStart > 0 && (text[lineStart - 1] == ' ' || text[lineStart - 1] == '\t')) --lineStart;
    if (lineStart > 0 && text[lineStart - 1] == '\n')
        return text.substr(0, lineStart) + insertion + text.substr(lineStart);
    return text.substr(0, at) + "\n" + insertion + text.substr(at);
}

}  // namespace

int main(int argc, char** argv) {
    ApplicationInfo info{
        "mfDictionary",
        "Print a dictionary with includes and macros expanded, query an entry, or set one in place.",
        {{"entry", "a/b/c", "the scoped entry to print, list (-keywords) or set (-set)"},
         {"set", "value", "replace the entry's value in the file, keeping everything else"},
         {"keywords", "", "list the keywords of the top level or of the -entry dictionary"},
         {"expand", "", "print the whole dictionary expanded (the default)"}},
        {"file"}};
    info.usesCase = false;
    return runApplication(argc, argv, info, [](const Arguments& args) {
        const fs::path file = args.positional().at(0);
        const std::string text = readText(file);
        const std::string fileName = file.string();

        if (auto value = args.find("set")) {
            const std::string scoped = args.value("entry");
            const std::string edited = edit(text, fileName, scoped, *value);
            const Dictionary check = Dictionary::parse(edited, fileName);
            if (!findEntry(check, scoped))
                throw Error("internal error: '" + scoped + "' missing after the edit");
            writeAtomically(file, edited);
            return 0;
        }

        const Dictionary dict = Dictionary::parse(text, fileName);
        const Dictionary* scope = &dict;
        const Entry* entry = nullptr;
        if (auto scoped = args.find("entry")) {
            entry = findEntry(dict, *scoped);
            if (!entry) throw InputError(dict.where(), "", "no entry '" + *scoped + "'");
            scope = entry->dict.get();
        }
        if (args.has("keywords")) {
            if (!scope)
                throw InputError(entry->where, "", "'" + args.value("entry") + "' is not a dictionary");
            for (const auto& key : scope->keys()) std::cout << key << "\n";
            return 0;
        }
        std::cout << (entry ? valueText(*entry) : dict.str());
        return 0;
    });
}
