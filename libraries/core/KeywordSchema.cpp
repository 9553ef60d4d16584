#include "core/KeywordSchema.hpp"

#include "core/Dictionary.hpp"
#include "core/Log.hpp"
#include "core/MessageText.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace mfdyn {

namespace {

std::string formatNumber(double value) {
    return formatKeywordNumber(value);
}

std::string joinWords(const std::vector<std::string>& words) {
    std::string s;
    for (const auto& w : words) s += (s.empty() ? "" : " | ") + w;
    return s;
}

std::string scoped(const Dictionary& dict, std::string_view key) {
    return (dict.scope().empty() ? std::string() : dict.scope() + "/") + std::string(key);
}

bool inside(const Keyword& k, double v) {
    if (k.lower && (k.lower->open ? !(v > k.lower->value) : !(v >= k.lower->value))) return false;
    if (k.upper && (k.upper->open ? !(v < k.upper->value) : !(v <= k.upper->value))) return false;
    return true;
}

}  // namespace

std::string formatKeywordNumber(double value) {
    // %g style with the fewest digits (6 at least) that read back as `value`, so that the value
    // shown is the value read: 1e-320 is "9.99989e-321", not "0.000000". std::to_chars and
    // std::from_chars neither throw (std::stod threw out_of_range for a subnormal, which reached
    // the user as "Error (internal): stod") nor depend on the locale.
    char text[64];
    std::string shown;
    for (int precision = 6; precision <= 17; ++precision) {
        const auto written =
            std::to_chars(text, text + sizeof text, value, std::chars_format::general, precision);
        shown.assign(text, written.ptr);
        double back = 0.0;
        const auto read = std::from_chars(text, written.ptr, back);
        if (!std::isfinite(value) || (read.ec == std::errc() && back == value)) break;
    }
    return shown;
}

// ------------------------------------------------------------------------------------------
// Keyword

std::string Keyword::typeText() const {
    switch (type) {
        case Type::scalar:
            return "a real number";
        case Type::integer:
            return "an integer";
        case Type::word:
            return "one of " + joinWords(words);
        case Type::vector:
            return length ? "a list of " + std::to_string(length) + " reals (...)" : "a list of reals (...)";
        case Type::switchValue:
            return "a switch (yes/no)";
        case Type::dictionary:
            return "a dictionary { ... }";
        case Type::wordList:
            return "a list of names (...)";
        case Type::table:
            return "a table of rows (...)";
        case Type::identifier:
            return "a name";
    }
    return "?";
}

std::string Keyword::boundsText() const {
    std::string s;
    if (lower) s += (lower->open ? "> " : ">= ") + formatNumber(lower->value);
    if (upper)
        s +=
            (s.empty() ? "" : " and ") + std::string(upper->open ? "< " : "<= ") + formatNumber(upper->value);
    return s;
}

std::string Keyword::kindText() const {
    switch (kind) {
        case Kind::required:
            return "required";
        case Kind::defaulted:
            return "default " + defaultValue;
        case Kind::optional:
            return "optional";
    }
    return "?";
}

std::string Keyword::sampleValue() const {
    if (!defaultValue.empty()) return defaultValue;
    if (!example.empty()) return example;
    switch (type) {
        case Type::word:
            return words.empty() ? "name" : words.front();
        case Type::switchValue:
            return "no";
        case Type::vector: {
            std::string zeros = "(";
            for (std::size_t i = 0; i < (length ? length : 3); ++i) zeros += i ? " 0" : "0";
            return zeros + ")";
        }
        case Type::dictionary:
            return "{ }";
        case Type::wordList:
            return "(name)";
        case Type::table:
            return "((0 (0 0 0)))";
        case Type::identifier:
            return "name";
        case Type::integer:
        case Type::scalar:
            break;
    }
    double v = 1.0;
    if (lower && !inside(*this, v)) v = lower->value + (lower->open ? 1.0 : 0.0);
    if (upper && !inside(*this, v)) v = upper->value - (upper->open ? 1.0 : 0.0);
    if (!inside(*this, v) && lower && upper) v = 0.5 * (lower->value + upper->value);
    return formatNumber(v);
}

// ------------------------------------------------------------------------------------------
// Declaration

namespace {
Keyword makeKeyword(std::string name, std::string unit, std::string meaning, Keyword::Type type) {
    Keyword k;
    k.name = std::move(name);
    k.unit = std::move(unit);
    k.meaning = std::move(meaning);
    k.type = type;
    return k;
}
}  // namespace

KeywordSchema& KeywordSchema::scalar(std::string name, std::string unit, std::string meaning) {
    keywords_.push_back(
        makeKeyword(std::move(name), std::move(unit), std::move(meaning), Keyword::Type::scalar));
    return *this;
}

KeywordSchema& KeywordSchema::integer(std::string name, std::string unit, std::string meaning) {
    keywords_.push_back(
        makeKeyword(std::move(name), std::move(unit), std::move(meaning), Keyword::Type::integer));
    return *this;
}

KeywordSchema& KeywordSchema::word(std::string name, std::vector<std::string> words, std::string meaning) {
    keywords_.push_back(makeKeyword(std::move(name), "-", std::move(meaning), Keyword::Type::word));
    keywords_.back().words = std::move(words);
    return *this;
}

KeywordSchema& KeywordSchema::vector(std::string name, std::string unit, std::string meaning) {
    keywords_.push_back(
        makeKeyword(std::move(name), std::move(unit), std::move(meaning), Keyword::Type::vector));
    return *this;
}

KeywordSchema& KeywordSchema::flag(std::string name, std::string meaning) {
    keywords_.push_back(makeKeyword(std::move(name), "-", std::move(meaning), Keyword::Type::switchValue));
    return *this;
}

KeywordSchema& KeywordSchema::dictionary(std::string name, std::string meaning) {
    keywords_.push_back(makeKeyword(std::move(name), "-", std::move(meaning), Keyword::Type::dictionary));
    return *this;
}

KeywordSchema& KeywordSchema::words(std::string name, std::string meaning) {
    keywords_.push_back(makeKeyword(std::move(name), "-", std::move(meaning), Keyword::Type::wordList));
    return *this;
}

KeywordSchema& KeywordSchema::identifier(std::string name, std::string meaning) {
    keywords_.push_back(makeKeyword(std::move(name), "-", std::move(meaning), Keyword::Type::identifier));
    return *this;
}

KeywordSchema& KeywordSchema::table(std::string name, std::string unit, std::string meaning) {
    keywords_.push_back(
        makeKeyword(std::move(name), std::move(unit), std::move(meaning), Keyword::Type::table));
    return *this;
}

Keyword& KeywordSchema::last(const char* modifier) {
    if (keywords_.empty())
        throw std::logic_error(family_ + " " + type_ + ": keyword schema modifier " + modifier +
                               "() before any keyword");
    return keywords_.back();
}

KeywordSchema& KeywordSchema::orDefault(double value) {
    Keyword& k = last("orDefault");
    if (k.type != Keyword::Type::scalar && k.type != Keyword::Type::integer)
        throw std::logic_error(family_ + " " + type_ + ": numeric default for non-numeric keyword " + k.name);
    if (!inside(k, value))
        throw std::logic_error(family_ + " " + type_ + ": default of " + k.name + " outside its bounds");
    k.kind = Keyword::Kind::defaulted;
    k.defaultValue = formatNumber(value);
    k.defaultNumber = value;
    return *this;
}

KeywordSchema& KeywordSchema::orDefault(int value) {
    return orDefault(double(value));
}

KeywordSchema& KeywordSchema::orDefault(bool value) {
    Keyword& k = last("orDefault");
    if (k.type != Keyword::Type::switchValue)
        throw std::logic_error(family_ + " " + type_ + ": switch default for keyword " + k.name);
    k.kind = Keyword::Kind::defaulted;
    k.defaultValue = value ? "yes" : "no";
    return *this;
}

KeywordSchema& KeywordSchema::orDefault(const char* value) {
    return orDefault(std::string(value));
}

KeywordSchema& KeywordSchema::orDefault(const std::string& value) {
    Keyword& k = last("orDefault");
    if (k.type != Keyword::Type::word && k.type != Keyword::Type::identifier)
        throw std::logic_error(family_ + " " + type_ + ": word default for keyword " + k.name);
    bool valid = k.type == Keyword::Type::identifier;
    for (const auto& w : k.words) valid = valid || w == value;
    if (!valid)
        throw std::logic_error(family_ + " " + type_ + ": default of " + k.name + " is not one of its words");
    k.kind = Keyword::Kind::defaulted;
    k.defaultValue = value;
    return *this;
}

KeywordSchema& KeywordSchema::orDefault(const std::vector<double>& value) {
    Keyword& k = last("orDefault");
    if (k.type != Keyword::Type::vector)
        throw std::logic_error(family_ + " " + type_ + ": vector default for keyword " + k.name);
    std::string text = "(";
    for (std::size_t i = 0; i < value.size(); ++i) {
        if (!inside(k, value[i]))
            throw std::logic_error(family_ + " " + type_ + ": default of " + k.name + " outside its bounds");
        text += (i ? " " : "") + formatNumber(value[i]);
    }
    if (k.length && value.size() != k.length)
        throw std::logic_error(family_ + " " + type_ + ": default of " + k.name + " has another length");
    k.kind = Keyword::Kind::defaulted;
    k.defaultValue = text + ")";
    k.defaultList = value;
    return *this;
}

KeywordSchema& KeywordSchema::orDefaultNames(const std::vector<std::string>& value) {
    Keyword& k = last("orDefaultNames");
    if (k.type != Keyword::Type::wordList || value.empty())
        throw std::logic_error(family_ + " " + type_ + ": list-of-names default for keyword " + k.name);
    std::string text = "(";
    for (std::size_t i = 0; i < value.size(); ++i) text += (i ? " " : "") + value[i];
    k.kind = Keyword::Kind::defaulted;
    k.defaultValue = text + ")";
    k.defaultNames = value;
    return *this;
}

KeywordSchema& KeywordSchema::optional() {
    last("optional").kind = Keyword::Kind::optional;
    return *this;
}

KeywordSchema& KeywordSchema::greaterThan(double bound) {
    last("greaterThan").lower = KeywordBound{bound, true};
    return *this;
}

KeywordSchema& KeywordSchema::atLeast(double bound) {
    last("atLeast").lower = KeywordBound{bound, false};
    return *this;
}

KeywordSchema& KeywordSchema::lessThan(double bound) {
    last("lessThan").upper = KeywordBound{bound, true};
    return *this;
}

KeywordSchema& KeywordSchema::atMost(double bound) {
    last("atMost").upper = KeywordBound{bound, false};
    return *this;
}

KeywordSchema& KeywordSchema::ofLength(std::size_t components) {
    Keyword& k = last("ofLength");
    if (k.type != Keyword::Type::vector)
        throw std::logic_error(family_ + " " + type_ + ": length of the non-vector keyword " + k.name);
    if (k.kind == Keyword::Kind::defaulted && k.defaultList.size() != components)
        throw std::logic_error(family_ + " " + type_ + ": default of " + k.name + " has another length");
    k.length = components;
    return *this;
}

KeywordSchema& KeywordSchema::example(std::string value) {
    last("example").example = std::move(value);
    return *this;
}

KeywordSchema& KeywordSchema::nested(KeywordSchema (*schema)()) {
    Keyword& k = last("nested");
    if (k.type != Keyword::Type::dictionary || !schema)
        throw std::logic_error(family_ + " " + type_ + ": nested schema for the non-dictionary keyword " +
                               k.name);
    k.nested = schema;
    return *this;
}

KeywordSchema& KeywordSchema::orEnclosing() {
    last("orEnclosing").orEnclosing = true;
    return *this;
}

KeywordSchema& KeywordSchema::append(const KeywordSchema& other) {
    for (const Keyword& k : other.keywords_) {
        if (find(k.name))
            throw std::logic_error(family_ + " " + type_ + ": keyword " + k.name + " declared twice");
        keywords_.push_back(k);
    }
    return *this;
}

KeywordSchema& KeywordSchema::rename(std::string family, std::string type) {
    family_ = std::move(family);
    type_ = std::move(type);
    return *this;
}

const Keyword* KeywordSchema::find(std::string_view name) const {
    for (const Keyword& k : keywords_)
        if (k.name == name) return &k;
    return nullptr;
}

std::string KeywordSchema::summary(const std::string& indent) const {
    std::size_t nameWidth = 0, unitWidth = 0, kindWidth = 0;
    for (const Keyword& k : keywords_) {
        nameWidth = std::max(nameWidth, k.name.size());
        unitWidth = std::max(unitWidth, k.unit.size());
        kindWidth = std::max(kindWidth, k.kindText().size());
    }
    std::string s;
    for (const Keyword& k : keywords_) {
        std::string line = indent + k.name + std::string(nameWidth + 2 - k.name.size(), ' ') + k.unit +
                           std::string(unitWidth + 2 - k.unit.size(), ' ') + k.kindText();
        std::string extra = k.type == Keyword::Type::word ? joinWords(k.words) : k.boundsText();
        if (k.orEnclosing) extra += std::string(extra.empty() ? "" : ", ") + "or in the enclosing dictionary";
        if (!extra.empty()) line += std::string(kindWidth + 2 - k.kindText().size(), ' ') + extra;
        s += line + "\n";
        if (k.nested) s += k.nested().summary(indent + "    ");
    }
    return s;
}

// ------------------------------------------------------------------------------------------
// Reading

KeywordValues KeywordSchema::read(const Dictionary& dict) const {
    // A key given for a missing keyword `name` that is a plausible typo of it: unread, and not
    // another keyword of this schema (`interval` missing and `intervall` given).
    const auto misspelt = [this](const Dictionary& in, const std::string& name) {
        std::vector<std::string> unread;
        for (const auto& e : in.entries())
            if (!e->read && !find(e->key)) unread.push_back(e->key);
        return closestMatch(name, unread);
    };
    KeywordValues out;
    out.dict_ = &dict;
    out.model_ = family_ + " " + type_;
    out.values_.reserve(keywords_.size());
    for (const Keyword& k : keywords_) {
        KeywordValues::Value v;
        v.keyword = k;
        // The model's own dictionary first; asking marks the key for did-you-mean suggestions.
        if (dict.found(k.name)) {
            v.holder = &dict;
        } else if (const Dictionary* up = dict.parent(); k.orEnclosing && up && up->found(k.name)) {
            v.holder = up;
        }
        if (!v.holder) {
            if (k.kind == Keyword::Kind::required) {
                std::string message = "missing keyword '" + k.name + "' (" + k.meaning + ", " + k.typeText() +
                                      (k.unit == "-" ? "" : " in " + k.unit) + "), required by " + family_ +
                                      " type '" + type_ + "'";
                if (k.orEnclosing && dict.parent())
                    message += "; looked for in '" + dict.scope() + "' and in the enclosing '" +
                               dict.parent()->scope() + "'";
                if (const std::string typo = misspelt(dict, k.name); !typo.empty())
                    message += " (found '" + excerpt(typo) + "': did you mean '" + k.name + "'?)";
                throw InputError(dict.where(), dict.scope(), message);
            }
            if (k.kind == Keyword::Kind::defaulted) {
                switch (k.type) {
                    case Keyword::Type::scalar:
                        v.number = k.defaultNumber;
                        break;
                    case Keyword::Type::integer:
                        v.integer = long(k.defaultNumber);
                        v.number = double(v.integer);
                        break;
                    case Keyword::Type::switchValue:
                        v.flag = k.defaultValue == "yes";
                        break;
                    case Keyword::Type::vector:
                        v.list = k.defaultList;
                        break;
                    case Keyword::Type::wordList:
                        v.names = k.defaultNames;
                        break;
                    default:
                        v.text = k.defaultValue;
                        break;
                }
                out.defaultsUsed_.push_back(k.name + " " + k.defaultValue);
                dict.noteDefault(scoped(dict, k.name) + " " + k.defaultValue);
            }
            out.values_.push_back(std::move(v));
            continue;
        }
        const Dictionary& from = *v.holder;
        const std::string unit = k.unit == "-" ? "" : " (" + k.unit + ")";
        switch (k.type) {
            case Keyword::Type::scalar:
            case Keyword::Type::integer: {
                if (k.type == Keyword::Type::integer) {
                    v.integer = from.get<long>(k.name);
                    v.number = double(v.integer);
                } else {
                    v.number = from.get<double>(k.name);
                }
                if (!std::isfinite(v.number) || !inside(k, v.number))
                    throw from.error(k.name, "expected a value " +
                                                 (k.boundsText().empty() ? std::string("that is finite")
                                                                         : k.boundsText()) +
                                                 unit + ", found " + formatNumber(v.number));
                break;
            }
            case Keyword::Type::word: {
                v.text = from.get<std::string>(k.name);
                bool valid = false;
                for (const auto& w : k.words) valid = valid || w == v.text;
                if (!valid) {
                    const std::string guess = closestMatch(v.text, k.words);
                    throw from.error(k.name, "expected one of " + joinWords(k.words) + ", found '" +
                                                 excerpt(v.text) + "'" +
                                                 (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
                }
                break;
            }
            case Keyword::Type::vector:
                v.list = from.get<std::vector<double>>(k.name);
                if (k.length && v.list.size() != k.length)
                    throw from.error(k.name, "expected " + std::to_string(k.length) + " values (" +
                                                 k.meaning + "), found " + std::to_string(v.list.size()));
                for (double x : v.list)
                    if (!std::isfinite(x) || !inside(k, x))
                        throw from.error(k.name, "expected components " + k.boundsText() + unit + ", found " +
                                                     formatNumber(x));
                break;
            case Keyword::Type::switchValue:
                v.flag = from.get<bool>(k.name);
                break;
            case Keyword::Type::dictionary: {
                const Dictionary& sub = from.subDict(k.name);
                if (k.nested) v.nested = std::make_shared<const KeywordValues>(k.nested().read(sub));
                break;
            }
            case Keyword::Type::wordList:
                v.names = from.get<std::vector<std::string>>(k.name);
                if (v.names.empty())
                    throw from.error(k.name, "expected at least one name (" + k.meaning + "), found ()");
                break;
            case Keyword::Type::table:
                from.entry(k.name);  // its rows are the model's to parse
                break;
            case Keyword::Type::identifier:
                v.text = from.get<std::string>(k.name);
                break;
        }
        out.values_.push_back(std::move(v));
    }
    if (!out.defaultsUsed_.empty()) {
        std::string line = out.model_ + " (" + dict.scope() + "): ";
        for (std::size_t i = 0; i < out.defaultsUsed_.size(); ++i)
            line += (i ? "; " : "") + out.defaultsUsed_[i] + " (default)";
        Log::info(line);
    }
    return out;
}

// ------------------------------------------------------------------------------------------
// Values

const KeywordValues::Value& KeywordValues::value(std::string_view name, Keyword::Type type) const {
    for (const Value& v : values_) {
        if (v.keyword.name != name) continue;
        const bool numeric = type == Keyword::Type::scalar && (v.keyword.type == Keyword::Type::scalar ||
                                                               v.keyword.type == Keyword::Type::integer);
        const bool freeName = type == Keyword::Type::word && v.keyword.type == Keyword::Type::identifier;
        if (v.keyword.type != type && !numeric && !freeName)
            throw std::logic_error(model_ + ": keyword '" + std::string(name) + "' is declared " +
                                   v.keyword.typeText() + " but read as another type");
        return v;
    }
    throw std::logic_error(model_ + ": keyword '" + std::string(name) +
                           "' is read but not declared in its schema");
}

double KeywordValues::scalar(std::string_view name) const {
    const Value& v = value(name, Keyword::Type::scalar);
    if (!v.holder && v.keyword.kind == Keyword::Kind::optional)
        throw std::logic_error(model_ + ": optional keyword '" + std::string(name) +
                               "' read without a check (use optionalScalar)");
    return v.number;
}

std::optional<double> KeywordValues::optionalScalar(std::string_view name) const {
    const Value& v = value(name, Keyword::Type::scalar);
    if (!v.holder && v.keyword.kind == Keyword::Kind::optional) return std::nullopt;
    return v.number;
}

long KeywordValues::integer(std::string_view name) const {
    return value(name, Keyword::Type::integer).integer;
}

const std::string& KeywordValues::word(std::string_view name) const {
    return value(name, Keyword::Type::word).text;
}

bool KeywordValues::flag(std::string_view name) const {
    return value(name, Keyword::Type::switchValue).flag;
}

const std::vector<double>& KeywordValues::vector(std::string_view name) const {
    return value(name, Keyword::Type::vector).list;
}

const Dictionary& KeywordValues::dictionary(std::string_view name) const {
    const Value& v = value(name, Keyword::Type::dictionary);
    if (!v.holder)
        throw std::logic_error(model_ + ": optional dictionary '" + std::string(name) + "' not given");
    return v.holder->subDict(name);
}

const KeywordValues& KeywordValues::nested(std::string_view name) const {
    const Value& v = value(name, Keyword::Type::dictionary);
    if (!v.keyword.nested)
        throw std::logic_error(model_ + ": dictionary '" + std::string(name) + "' has no nested schema");
    if (!v.nested)
        throw std::logic_error(model_ + ": optional dictionary '" + std::string(name) +
                               "' not given (check given() first)");
    return *v.nested;
}

const std::vector<std::string>& KeywordValues::words(std::string_view name) const {
    return value(name, Keyword::Type::wordList).names;
}

bool KeywordValues::given(std::string_view name) const {
    for (const Value& v : values_)
        if (v.keyword.name == name) return v.holder != nullptr;
    throw std::logic_error(model_ + ": keyword '" + std::string(name) +
                           "' is asked for but not declared in its schema");
}

InputError KeywordValues::error(std::string_view name, const std::string& message) const {
    for (const Value& v : values_)
        if (v.keyword.name == name) return (v.holder ? *v.holder : *dict_).error(name, message);
    throw std::logic_error(model_ + ": keyword '" + std::string(name) + "' is not declared in its schema");
}

}  // namespace mfdyn
