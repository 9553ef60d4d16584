#pragma once
// A dictionary in OpenFOAM syntax: `key value;`, nested `name { ... }`, lists in parentheses,
// words, "strings", integers, reals, `//` and `/* */` comments, `#include "file"`,
// `#includeEtc "name"`, `$name` and scoped `$a.b.c` macros. The grammar (Boost.Spirit X3) lives
// in DictionaryParser.cpp only, so no other translation unit pays for it.
//
// Reading is tracked: every entry remembers whether a model looked at it, and every dictionary
// remembers the keys that were asked for. unusedEntries() turns that into "never read, did you
// mean ...?" warnings at the end of set-up.
#include "core/Error.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace mfdyn {

class Dictionary;

// One value token. Booleans are words (yes/no/on/off/true/false) interpreted by get<bool>.
struct Token {
    enum class Kind { word, string, integer, real, list, dictionary };
    Kind kind = Kind::word;
    std::string text;                  // word, or string without its quotes
    std::int64_t integer = 0;          // for Kind::integer
    double real = 0.0;                 // for Kind::real (and integer, converted)
    std::vector<Token> list;           // for Kind::list
    std::shared_ptr<Dictionary> dict;  // for Kind::dictionary (a `{ }` inside a list)
    SourceLocation where;

    bool isNumber() const { return kind == Kind::integer || kind == Kind::real; }
    double number() const { return kind == Kind::integer ? double(integer) : real; }
    // The token as it would be written in a dictionary.
    std::string str() const;
};

// One `key value...;` or `key { ... }` entry.
struct Entry {
    std::string key;
    std::vector<Token> tokens;         // the value, for a primitive entry
    std::unique_ptr<Dictionary> dict;  // the value, for a dictionary entry
    SourceLocation where;              // of the key
    bool fromInclude = false;          // came from #include/#includeEtc/$macro: may be overridden
    // Byte span of the value in its file (for mfDictionary -set editing in place); for a
    // dictionary entry, the span of the braces' contents. Only valid when where.file is set.
    std::size_t valueBegin = 0, valueEnd = 0;
    mutable bool read = false;

    bool isDict() const { return dict != nullptr; }
    // A deep copy (sub-dictionaries included), for macro expansion and Dictionary copies.
    std::unique_ptr<Entry> clone() const;
};

struct UnusedEntry {
    std::string scopedKey;  // "materials/target/rho0"
    SourceLocation where;
    std::string suggestion;  // closest key asked for in the same scope, or empty
};

struct ReadOptions {
    // Searched in order by #includeEtc; empty means the toolkit's etc/ (see etcDirectories()).
    std::vector<std::filesystem::path> etcDirectories;
};

// The directories #includeEtc searches: $MFDYN_ETC (colon-separated), then the etc/ of the
// source tree or installation this library belongs to.
std::vector<std::filesystem::path> etcDirectories();

class Dictionary {
public:
    Dictionary() = default;
    explicit Dictionary(std::string name) : name_(std::move(name)) {}
    Dictionary(const Dictionary& other);
    Dictionary& operator=(const Dictionary& other);
    Dictionary(Dictionary&&) noexcept;
    Dictionary& operator=(Dictionary&&) noexcept;
    ~Dictionary();

    // Parse a file. Throws InputError naming file:line:column on any syntax or include error.
    static Dictionary read(const std::filesystem::path& file, const ReadOptions& options = {});
    // Parse text; `fileName` is used in messages and as the base for relative #include.
    static Dictionary parse(std::string_view text, const std::string& fileName,
                            const ReadOptions& options = {});

    // "materials/target/strength" (empty for a top-level dictionary).
    const std::string& scope() const { return name_; }
    // The file this dictionary (or its top-level parent) was read from.
    const SourceLocation& where() const { return where_; }
    const Dictionary* parent() const { return parent_; }
    const Dictionary& topLevel() const;

    bool found(std::string_view key) const;
    bool isDict(std::string_view key) const;
    std::vector<std::string> keys() const;
    std::size_t size() const { return entries_.size(); }
    const std::vector<std::unique_ptr<Entry>>& entries() const { return entries_; }

    // Look-up; both mark the entry read. entry() throws InputError when missing.
    const Entry* findEntry(std::string_view key) const;
    const Entry& entry(std::string_view key) const;
    const Dictionary* findDict(std::string_view key) const;
    const Dictionary& subDict(std::string_view key) const;
    // Scoped look-up "a/b/c" or "a.b.c" (used by mfDictionary -entry and $macros).
    const Entry* findScoped(std::string_view scopedKey) const;
    // Look-up that marks nothing read or asked (macro expansion, editing tools).
    const Entry* peek(std::string_view key) const;

    // Typed look-up; the conversions are ValueTraits<T> below. get throws when the key is missing
    // or the value has the wrong form; the message names file:line:column, scope and expectation.
    template <class T>
    T get(std::string_view key) const;
    template <class T>
    T getOrDefault(std::string_view key, const T& fallback) const;
    template <class T>
    std::optional<T> getOptional(std::string_view key) const;

    // Defaults that getOrDefault used, as "scope/key value" (echoed in the log).
    const std::vector<std::string>& defaultsUsed() const { return defaultsUsed_; }

    // Entries never read, recursively, with did-you-mean suggestions from the keys asked for.
    std::vector<UnusedEntry> unusedEntries() const;
    // Mark every entry read (for dictionaries that are passed through rather than interpreted).
    void markAllRead() const;

    // Editing (mfDictionary -set, solvers building sub-dictionaries in code).
    // `valueText` is parsed as the tokens of a primitive entry, or as a dictionary body when it
    // starts with '{'.
    void set(std::string_view key, std::string_view valueText);
    Dictionary& addDict(std::string_view key);
    bool remove(std::string_view key);

    // OpenFOAM-style text, macros and includes expanded.
    std::string str(int indent = 0) const;

    // An InputError located at the entry `key` (or at the dictionary when it is missing).
    InputError error(std::string_view key, const std::string& message) const;

    // Parser and builder internals.
    Entry& addEntry(std::unique_ptr<Entry> entry);
    void setScope(const std::string& name, const Dictionary* parent);
    void setWhere(const SourceLocation& where) { where_ = where; }
    void noteAsked(std::string_view key) const { asked_.emplace(key); }
    void noteDefault(std::string entry) const { defaultsUsed_.push_back(std::move(entry)); }
    std::size_t closeBraceOffset = 0;  // offset of '}' (or end of file) for appending entries

private:
    void rebuildIndex();
    void repointChildren();  // after a move: children still point at the moved-from object
    void collectUnused(std::vector<UnusedEntry>& out) const;

    std::string name_;
    SourceLocation where_;
    const Dictionary* parent_ = nullptr;
    std::vector<std::unique_ptr<Entry>> entries_;
    std::map<std::string, std::size_t, std::less<>> index_;
    mutable std::set<std::string, std::less<>> asked_;
    mutable std::vector<std::string> defaultsUsed_;
};

// Conversions from an entry's tokens to C++ values. Specialised in Dictionary.cpp for double,
// float, int, long, unsigned long, long long, bool, std::string, std::vector<double>,
// std::vector<int>, std::vector<std::string>; in core/Tensor.hpp for Eigen vectors and matrices.
// `describe` says what was expected, for messages ("a real number", "a list of 3 reals").
template <class T>
struct ValueTraits {
    static T convert(const Entry& entry, const Dictionary& scope);
    static std::string describe();
};

template <class T>
T Dictionary::get(std::string_view key) const {
    return ValueTraits<T>::convert(entry(key), *this);
}

template <class T>
T Dictionary::getOrDefault(std::string_view key, const T& fallback) const {
    if (const Entry* e = findEntry(key)) return ValueTraits<T>::convert(*e, *this);
    noteDefault((name_.empty() ? std::string() : name_ + "/") + std::string(key));
    return fallback;
}

template <class T>
std::optional<T> Dictionary::getOptional(std::string_view key) const {
    if (const Entry* e = findEntry(key)) return ValueTraits<T>::convert(*e, *this);
    return std::nullopt;
}

// Levenshtein distance, for did-you-mean suggestions everywhere (unknown keys, unknown types).
std::size_t editDistance(std::string_view a, std::string_view b);
// The candidate closest to `word` when it is close enough to be a plausible typo, else "".
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace mfdyn
