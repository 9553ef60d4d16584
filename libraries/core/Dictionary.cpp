// Dictionary look-up, tracking, printing and the typed conversions. The grammar and the builder
// live in DictionaryParser.cpp (the only user of Boost.Spirit).
#include "core/Dictionary.hpp"

#include "core/MessageText.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <type_traits>

namespace mfdyn {

// ------------------------------------------------------------------------------------------
// Token and Entry

namespace {

std::string quote(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') q += '\\';
        q += c;
    }
    return q + "\"";
}

// A key as the grammar reads it back: bare when it is a word (DictionaryParser.cpp: no leading
// digit, no delimiter, blank, control byte or comment opening), else quoted. Keys written quoted,
// such as "my (key", printed bare would not parse again (fuzz fixture quotedKeySyntaxCharacters).
std::string keyText(const std::string& key) {
    bool bare = !key.empty() && !(key.front() >= '0' && key.front() <= '9');
    for (std::size_t i = 0; bare && i < key.size(); ++i) {
        const auto c = static_cast<unsigned char>(key[i]);
        const bool delimiter = c <= ' ' || c == 127 || c == '"' || c == ';' || c == '{' || c == '}' ||
                               c == '(' || c == ')' || c == '$' || c == '#';
        const bool comment = c == '/' && i + 1 < key.size() && (key[i + 1] == '/' || key[i + 1] == '*');
        bare = !delimiter && !comment;
    }
    return bare ? key : quote(key);
}

// Shortest text that reads back as the same double, and still reads as a real, not an integer.
std::string formatReal(double x) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    std::string s(buf, r.ptr);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // 'n': inf and nan stay as they are
    return s;
}

std::string inlineBody(const Dictionary& dict);

std::string joinTokens(const std::vector<Token>& tokens) {
    std::string s;
    for (const Token& t : tokens) {
        if (!s.empty()) s += ' ';
        s += t.str();
    }
    return s;
}

std::string inlineBody(const Dictionary& dict) {
    std::string s;
    for (const auto& e : dict.entries()) {
        s += keyText(e->key);
        if (e->isDict()) {
            s += " { " + inlineBody(*e->dict) + "} ";
        } else {
            if (!e->tokens.empty()) s += ' ' + joinTokens(e->tokens);
            s += "; ";
        }
    }
    return s;
}

Token cloneToken(const Token& t) {
    Token c = t;
    if (t.dict) c.dict = std::make_shared<Dictionary>(*t.dict);
    for (Token& sub : c.list) sub = cloneToken(sub);
    return c;
}

}  // namespace

std::string Token::str() const {
    switch (kind) {
        case Kind::word:
            return text;
        case Kind::string:
            return quote(text);
        case Kind::integer:
            return text.empty() ? std::to_string(integer) : text;
        case Kind::real:
            return text.empty() ? formatReal(real) : text;
        case Kind::list:
            return "(" + joinTokens(list) + ")";
        case Kind::dictionary:
            return dict ? "{ " + inlineBody(*dict) + "}" : "{ }";
    }
    return text;
}

std::unique_ptr<Entry> Entry::clone() const {
    auto e = std::make_unique<Entry>();
    e->key = key;
    e->tokens.reserve(tokens.size());
    for (const Token& t : tokens) e->tokens.push_back(cloneToken(t));
    if (dict) e->dict = std::make_unique<Dictionary>(*dict);
    e->where = where;
    e->fromInclude = fromInclude;
    e->valueBegin = valueBegin;
    e->valueEnd = valueEnd;
    e->read = read;
    return e;
}

// ------------------------------------------------------------------------------------------
// Copying and moving: children point back to their parent, so both must re-point them.

Dictionary::Dictionary(const Dictionary& other)
    : closeBraceOffset(other.closeBraceOffset),
      name_(other.name_),
      where_(other.where_),
      asked_(other.asked_),
      defaultsUsed_(other.defaultsUsed_) {
    // A copy stands alone: pointing at the original's parent could dangle.
    entries_.reserve(other.entries_.size());
    for (const auto& e : other.entries_) entries_.push_back(e->clone());
    rebuildIndex();
    // The clones carry the original's scope names already, and each cloned child dictionary has
    // re-pointed its own children: only this level's are left. (setScope here walked the whole
    // subtree at every level of a copy, so copying a value nested d deep cost d times its size.)
    parent_ = nullptr;
    repointChildren();
}

Dictionary& Dictionary::operator=(const Dictionary& other) {
    if (this != &other) {
        Dictionary copy(other);
        const Dictionary* parent = parent_;
        *this = std::move(copy);
        setScope(name_, parent);
    }
    return *this;
}

Dictionary::Dictionary(Dictionary&& other) noexcept
    : closeBraceOffset(other.closeBraceOffset),
      name_(std::move(other.name_)),
      where_(std::move(other.where_)),
      parent_(other.parent_),
      entries_(std::move(other.entries_)),
      index_(std::move(other.index_)),
      asked_(std::move(other.asked_)),
      defaultsUsed_(std::move(other.defaultsUsed_)) {
    other.entries_.clear();
    other.index_.clear();
    repointChildren();
}

Dictionary& Dictionary::operator=(Dictionary&& other) noexcept {
    if (this != &other) {
        closeBraceOffset = other.closeBraceOffset;
        name_ = std::move(other.name_);
        where_ = std::move(other.where_);
        parent_ = other.parent_;
        entries_ = std::move(other.entries_);
        index_ = std::move(other.index_);
        asked_ = std::move(other.asked_);
        defaultsUsed_ = std::move(other.defaultsUsed_);
        other.entries_.clear();
        other.index_.clear();
        repointChildren();
    }
    return *this;
}

Dictionary::~Dictionary() = default;

void Dictionary::repointChildren() {
    const auto repointTokens = [this](auto& self, std::vector<Token>& tokens) -> void {
        for (Token& t : tokens) {
            if (t.dict) t.dict->parent_ = this;
            self(self, t.list);
        }
    };
    for (auto& e : entries_) {
        if (e->dict) e->dict->parent_ = this;
        repointTokens(repointTokens, e->tokens);
    }
}

namespace {
void adoptTokens(std::vector<Token>& tokens, const std::string& scope, const Dictionary* parent) {
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        Token& t = tokens[i];
        if (t.dict) t.dict->setScope(scope + "[" + std::to_string(i) + "]", parent);
        adoptTokens(t.list, scope, parent);
    }
}
std::string joinScope(const std::string& scope, const std::string& key) {
    return scope.empty() ? key : scope + "/" + key;
}
}  // namespace

void Dictionary::setScope(const std::string& name, const Dictionary* parent) {
    name_ = name;
    parent_ = parent;
    for (auto& e : entries_) {
        const std::string child = joinScope(name_, e->key);
        if (e->dict) e->dict->setScope(child, this);
        adoptTokens(e->tokens, child, this);
    }
}

void Dictionary::rebuildIndex() {
    index_.clear();
    for (std::size_t i = 0; i < entries_.size(); ++i) index_[entries_[i]->key] = i;
}

// ------------------------------------------------------------------------------------------
// Look-up

const Dictionary& Dictionary::topLevel() const {
    const Dictionary* d = this;
    while (d->parent_) d = d->parent_;
    return *d;
}

const Entry* Dictionary::peek(std::string_view key) const {
    const auto it = index_.find(key);
    return it == index_.end() ? nullptr : entries_[it->second].get();
}

bool Dictionary::found(std::string_view key) const {
    noteAsked(key);
    return peek(key) != nullptr;
}

bool Dictionary::isDict(std::string_view key) const {
    noteAsked(key);
    const Entry* e = peek(key);
    return e && e->isDict();
}

std::vector<std::string> Dictionary::keys() const {
    std::vector<std::string> k;
    k.reserve(entries_.size());
    for (const auto& e : entries_) k.push_back(e->key);
    return k;
}

const Entry* Dictionary::findEntry(std::string_view key) const {
    noteAsked(key);
    const Entry* e = peek(key);
    if (e) e->read = true;
    return e;
}

const Entry& Dictionary::entry(std::string_view key) const {
    if (const Entry* e = findEntry(key)) return *e;
    // A plausible typo among the keys nobody read or asked for ("intervall" for "interval"): one
    // that was read or asked for is some other keyword.
    std::vector<std::string> unread;
    for (const auto& e : entries_)
        if (!e->read && e->key != key && !asked_.count(e->key)) unread.push_back(e->key);
    const std::string typo = closestMatch(key, unread);
    throw InputError(
        where_, name_,
        "missing keyword '" + std::string(key) + "'" +
            (typo.empty() ? std::string()
                          : " (found '" + excerpt(typo) + "': did you mean '" + std::string(key) + "'?)"));
}

const Dictionary* Dictionary::findDict(std::string_view key) const {
    const Entry* e = findEntry(key);
    return e && e->isDict() ? e->dict.get() : nullptr;
}

const Dictionary& Dictionary::subDict(std::string_view key) const {
    const Entry& e = entry(key);
    if (!e.isDict())
        throw InputError(e.where, name_, "keyword '" + std::string(key) + "': expected a dictionary { ... }");
    return *e.dict;
}

const Entry* Dictionary::findScoped(std::string_view scopedKey) const {
    if (const Entry* e = findEntry(scopedKey)) return e;
    const std::size_t cut = scopedKey.find_first_of("/.");
    if (cut == std::string_view::npos) return nullptr;
    if (cut == 0) return findScoped(scopedKey.substr(1));  // a leading '/' means this dictionary
    const Dictionary* d = findDict(scopedKey.substr(0, cut));
    return d ? d->findScoped(scopedKey.substr(cut + 1)) : nullptr;
}

// ------------------------------------------------------------------------------------------
// Tracking

void Dictionary::collectUnused(std::vector<UnusedEntry>& out) const {
    std::vector<std::string> asked(asked_.begin(), asked_.end());
    for (const auto& e : entries_) {
        if (!e->read) {
            std::vector<std::string> candidates;
            for (const auto& a : asked)
                if (a != e->key && !peek(a)) candidates.push_back(a);
            out.push_back({joinScope(name_, e->key), e->where, closestMatch(e->key, candidates)});
            continue;
        }
        if (e->dict) e->dict->collectUnused(out);
        std::vector<const std::vector<Token>*> lists{&e->tokens};
        while (!lists.empty()) {
            const auto* l = lists.back();
            lists.pop_back();
            for (const Token& t : *l) {
                if (t.dict) t.dict->collectUnused(out);
                if (!t.list.empty()) lists.push_back(&t.list);
            }
        }
    }
}

std::vector<UnusedEntry> Dictionary::unusedEntries() const {
    std::vector<UnusedEntry> out;
    collectUnused(out);
    return out;
}

namespace {
void markTokensRead(const std::vector<Token>& tokens) {
    for (const Token& t : tokens) {
        if (t.dict) t.dict->markAllRead();
        markTokensRead(t.list);
    }
}
}  // namespace

void Dictionary::markAllRead() const {
    for (const auto& e : entries_) {
        e->read = true;
        if (e->dict) e->dict->markAllRead();
        markTokensRead(e->tokens);
    }
}

// ------------------------------------------------------------------------------------------
// Editing

Entry& Dictionary::addEntry(std::unique_ptr<Entry> entry) {
    const std::string scope = joinScope(name_, entry->key);
    if (entry->dict) entry->dict->setScope(scope, this);
    adoptTokens(entry->tokens, scope, this);
    if (const auto it = index_.find(entry->key); it != index_.end()) {
        entries_[it->second] = std::move(entry);
        return *entries_[it->second];
    }
    index_.emplace(entry->key, entries_.size());
    entries_.push_back(std::move(entry));
    return *entries_.back();
}

Dictionary& Dictionary::addDict(std::string_view key) {
    if (const Entry* e = peek(key); e && e->isDict()) return *e->dict;
    auto e = std::make_unique<Entry>();
    e->key = std::string(key);
    e->where = where_;
    e->dict = std::make_unique<Dictionary>();
    e->dict->setWhere(where_);
    e->dict->closeBraceOffset = std::string::npos;
    return *addEntry(std::move(e)).dict;
}

bool Dictionary::remove(std::string_view key) {
    const auto it = index_.find(key);
    if (it == index_.end()) return false;
    entries_.erase(entries_.begin() + std::ptrdiff_t(it->second));
    rebuildIndex();
    return true;
}

// ------------------------------------------------------------------------------------------
// Printing and errors

std::string Dictionary::str(int indent) const {
    const std::string pad(std::size_t(std::max(indent, 0)) * 4, ' ');
    std::string s;
    for (const auto& e : entries_) {
        if (e->isDict()) {
            s += pad + keyText(e->key) + "\n" + pad + "{\n" + e->dict->str(indent + 1) + pad + "}\n";
        } else {
            s += pad + keyText(e->key);
            if (!e->tokens.empty()) s += ' ' + joinTokens(e->tokens);
            s += ";\n";
        }
    }
    return s;
}

InputError Dictionary::error(std::string_view key, const std::string& message) const {
    const Entry* e = peek(key);
    return InputError(e ? e->where : where_, name_, "keyword '" + std::string(key) + "': " + message);
}

// ------------------------------------------------------------------------------------------
// Typed conversions

namespace {

// What an entry holds, quoted in a short excerpt: the value may be a whole file's worth of words.
std::string describeValue(const Entry& e) {
    if (e.isDict()) return "a dictionary";
    if (e.tokens.empty()) return "an empty value";
    if (e.tokens.size() > 1)
        return std::to_string(e.tokens.size()) + " values '" + excerpt(joinTokens(e.tokens)) + "'";
    const Token& t = e.tokens.front();
    switch (t.kind) {
        case Token::Kind::word:
            return "the word '" + excerpt(t.text) + "'";
        case Token::Kind::string:
            return "the string " + excerpt(t.str());
        case Token::Kind::integer:
            return "the integer " + excerpt(t.str());
        case Token::Kind::real:
            return "the real " + excerpt(t.str());
        case Token::Kind::list:
            return "a list of " + std::to_string(t.list.size()) + " items";
        case Token::Kind::dictionary:
            return "a dictionary";
    }
    return "?";
}

// "inf", "-Infinity", "nan": the spellings strtod would read as a non-finite number.
bool isNonFiniteWord(std::string_view w) {
    if (!w.empty() && (w.front() == '+' || w.front() == '-')) w.remove_prefix(1);
    std::string lower;
    for (char c : w) lower += char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return lower == "inf" || lower == "infinity" || lower.rfind("nan", 0) == 0;
}

[[noreturn]] void typeError(const Entry& e, const Dictionary& scope, const std::string& expected,
                            const std::string& found) {
    const SourceLocation& at =
        !e.tokens.empty() && e.tokens.front().where.known() ? e.tokens.front().where : e.where;
    throw InputError(at, scope.scope(), "keyword '" + e.key + "': expected " + expected + ", found " + found);
}

const Token& single(const Entry& e, const Dictionary& scope, const std::string& expected) {
    if (e.isDict() || e.tokens.size() != 1) typeError(e, scope, expected, describeValue(e));
    return e.tokens.front();
}

template <class T>
T integerValue(const Entry& e, const Dictionary& scope) {
    const std::string expected = ValueTraits<T>::describe();
    const Token& t = single(e, scope, expected);
    if (t.kind != Token::Kind::integer) typeError(e, scope, expected, describeValue(e));
    if constexpr (std::is_unsigned_v<T>) {
        if (t.integer < 0) typeError(e, scope, expected, describeValue(e));
        if (std::uint64_t(t.integer) > std::numeric_limits<T>::max())
            typeError(e, scope, expected, describeValue(e) + " (out of range)");
    } else {
        if (t.integer < std::int64_t(std::numeric_limits<T>::min()) ||
            t.integer > std::int64_t(std::numeric_limits<T>::max()))
            typeError(e, scope, expected, describeValue(e) + " (out of range)");
    }
    return T(t.integer);
}

const std::vector<Token>& listValue(const Entry& e, const Dictionary& scope, const std::string& expected) {
    const Token& t = single(e, scope, expected);
    if (t.kind != Token::Kind::list) typeError(e, scope, expected, describeValue(e));
    return t.list;
}

}  // namespace

template <>
std::string ValueTraits<double>::describe() {
    return "a real number";
}
template <>
std::string ValueTraits<float>::describe() {
    return "a real number";
}
template <>
std::string ValueTraits<int>::describe() {
    return "an integer";
}
template <>
std::string ValueTraits<long>::describe() {
    return "an integer";
}
template <>
std::string ValueTraits<long long>::describe() {
    return "an integer";
}
template <>
std::string ValueTraits<unsigned long>::describe() {
    return "a non-negative integer";
}
template <>
std::string ValueTraits<bool>::describe() {
    return "a switch (yes/no, on/off, true/false)";
}
template <>
std::string ValueTraits<std::string>::describe() {
    return "a word or \"string\"";
}
template <>
std::string ValueTraits<std::vector<double>>::describe() {
    return "a list of reals (...)";
}
template <>
std::string ValueTraits<std::vector<int>>::describe() {
    return "a list of integers (...)";
}
template <>
std::string ValueTraits<std::vector<std::string>>::describe() {
    return "a list of words (...)";
}

template <>
std::string ValueTraits<std::string>::convert(const Entry& e, const Dictionary& scope) {
    const Token& t = single(e, scope, describe());
    if (t.kind != Token::Kind::word && t.kind != Token::Kind::string)
        typeError(e, scope, describe(), describeValue(e));
    return t.text;
}

template <>
double ValueTraits<double>::convert(const Entry& e, const Dictionary& scope) {
    const Token& t = single(e, scope, describe());
    // The parser reads no inf or nan (they are words; 1e999 is out of range), so a non-finite
    // number can only come from a token built in code; no caller reads one on purpose (a bound
    // such as "no limit" is an optional keyword, not inf), so it is refused here as well.
    if (!t.isNumber()) {
        const bool nonFinite =
            t.kind == Token::Kind::word || t.kind == Token::Kind::string ? isNonFiniteWord(t.text) : false;
        typeError(
            e, scope, describe(),
            describeValue(e) + (nonFinite ? " (infinite and not-a-number values are not accepted)" : ""));
    }
    if (!std::isfinite(t.number()))
        typeError(e, scope, describe(),
                  "a non-finite value (infinite and not-a-number values are not accepted)");
    return t.number();
}

template <>
float ValueTraits<float>::convert(const Entry& e, const Dictionary& scope) {
    return float(ValueTraits<double>::convert(e, scope));
}

template <>
int ValueTraits<int>::convert(const Entry& e, const Dictionary& scope) {
    return integerValue<int>(e, scope);
}

template <>
long ValueTraits<long>::convert(const Entry& e, const Dictionary& scope) {
    return integerValue<long>(e, scope);
}

template <>
long long ValueTraits<long long>::convert(const Entry& e, const Dictionary& scope) {
    return integerValue<long long>(e, scope);
}

template <>
unsigned long ValueTraits<unsigned long>::convert(const Entry& e, const Dictionary& scope) {
    return integerValue<unsigned long>(e, scope);
}

template <>
bool ValueTraits<bool>::convert(const Entry& e, const Dictionary& scope) {
    const Token& t = single(e, scope, describe());
    if (t.kind == Token::Kind::word) {
        if (t.text == "yes" || t.text == "on" || t.text == "true") return true;
        if (t.text == "no" || t.text == "off" || t.text == "false") return false;
    }
    typeError(e, scope, describe(), describeValue(e));
}

template <>
std::vector<double> ValueTraits<std::vector<double>>::convert(const Entry& e, const Dictionary& scope) {
    std::vector<double> v;
    for (const Token& t : listValue(e, scope, describe())) {
        if (!t.isNumber())
            typeError(
                e, scope, describe(),
                "the item '" + excerpt(t.str()) + "'" +
                    (isNonFiniteWord(t.text) ? " (infinite and not-a-number values are not accepted)" : ""));
        if (!std::isfinite(t.number()))
            typeError(e, scope, describe(),
                      "a non-finite item (infinite and not-a-number values are not accepted)");
        v.push_back(t.number());
    }
    return v;
}

template <>
std::vector<int> ValueTraits<std::vector<int>>::convert(const Entry& e, const Dictionary& scope) {
    std::vector<int> v;
    for (const Token& t : listValue(e, scope, describe())) {
        if (t.kind != Token::Kind::integer || t.integer < std::numeric_limits<int>::min() ||
            t.integer > std::numeric_limits<int>::max())
            typeError(e, scope, describe(), "the item '" + excerpt(t.str()) + "'");
        v.push_back(int(t.integer));
    }
    return v;
}

template <>
std::vector<std::string> ValueTraits<std::vector<std::string>>::convert(const Entry& e,
                                                                        const Dictionary& scope) {
    std::vector<std::string> v;
    for (const Token& t : listValue(e, scope, describe())) {
        if (t.kind != Token::Kind::word && t.kind != Token::Kind::string)
            typeError(e, scope, describe(), "the item '" + excerpt(t.str()) + "'");
        v.push_back(t.text);
    }
    return v;
}

// ------------------------------------------------------------------------------------------
// Suggestions and etc directories

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates) {
    // Beyond a third of the word the "typo" is a different word; short words still allow two edits.
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    std::string best;
    std::size_t bestDistance = limit + 1;
    for (const auto& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

std::vector<std::filesystem::path> etcDirectories() {
    std::vector<std::filesystem::path> dirs;
    if (const char* env = std::getenv("MFDYN_ETC")) {
        std::string_view rest = env;
        while (!rest.empty()) {
            const std::size_t colon = rest.find(':');
            const std::string_view part = rest.substr(0, colon);
            if (!part.empty()) dirs.emplace_back(part);
            if (colon == std::string_view::npos) break;
            rest.remove_prefix(colon + 1);
        }
    }
    // The installed etc/ wins over the source tree's, which only serves runs from a build tree.
    std::error_code ec;
#ifdef MFDYN_INSTALL_ETC
    if (std::filesystem::is_directory(MFDYN_INSTALL_ETC, ec)) dirs.emplace_back(MFDYN_INSTALL_ETC);
#endif
#ifdef MFDYN_SOURCE_ETC
    if (std::filesystem::is_directory(MFDYN_SOURCE_ETC, ec)) dirs.emplace_back(MFDYN_SOURCE_ETC);
#endif
    return dirs;
}

}  // namespace mfdyn
