#pragma once
// The keyword schema of a model (STYLE.md conventions 2, 3, 11): every parameter declared once,
// with its camelCase name, SI unit, kind (required, default value, optional), value type, bounds
// and one-line meaning. The constructor reads its dictionary through the schema; the same
// declaration gives the validation messages, the defaults echoed in the log, `-listModels` and
// `-describe`, and the generated doc/models pages (applications/utilities/mfDoc).
//
// A model declares it as a static function, found by the registration (core/Registry.hpp):
//
//     KeywordSchema MieGruneisen::keywords() {
//         return KeywordSchema("equationOfState", "mieGruneisen")
//             .scalar("c0", "m/s", "bulk sound speed").greaterThan(0).orEnclosing()
//             .word("hugoniot", {"cubic", "linearUsUp"}, "reference curve in compression").orDefault("cubic")
//             .scalar("minimumPressure", "Pa", "tension cut-off").atMost(0).optional();
//     }
//
//     MieGruneisen::MieGruneisen(const Dictionary& dict) : EquationOfState(dict) {
//         const KeywordValues v = keywords().read(dict);
//         c0_ = v.scalar("c0");
//         ...
//     }
//
// read() checks every declared keyword at once, in declaration order: a missing required one, a
// value of the wrong type, outside its bounds or not among its words is an InputError at the file
// and line ("keyword 'c0': expected a value > 0 (m/s), found -3"). Defaults are applied and echoed
// to the log, one line per construction. Asking KeywordValues for a name the schema does not
// declare is a programming error (std::logic_error naming the model).
//
// `orEnclosing` keywords may also be given in the enclosing dictionary (a material's constants
// shared by its equation of state and strength law); an entry in the model's own dictionary wins.
#include "core/Error.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mfdyn {

class Dictionary;
class KeywordSchema;
class KeywordValues;

struct KeywordBound {
    double value = 0.0;
    bool open = false;  // excluded: a modulus > 0
};

struct Keyword {
    enum class Kind { required, defaulted, optional };
    // wordList: a list of names, `(wall lid)`; table: a list of rows the model parses itself
    // (a time table `((0 (0 0 0)) (1e-3 (0 -1 0)))`), for which the schema checks presence only.
    // identifier: one free name (a field's), where `word` is one of a fixed set.
    enum class Type { scalar, integer, word, vector, switchValue, dictionary, wordList, table, identifier };

    std::string name;
    std::string unit;  // SI; "-" for dimensionless
    std::string meaning;
    Kind kind = Kind::required;
    Type type = Type::scalar;
    std::string defaultValue;               // as written in a dictionary: "7", "cubic", "yes"
    double defaultNumber = 0.0;             // the default of a scalar or integer, exactly
    std::vector<double> defaultList;        // the default of a vector
    std::vector<std::string> defaultNames;  // the default of a list of names
    std::size_t length = 0;                 // the number of components of a vector; 0: any
    std::vector<std::string> words;         // the valid words of Type::word
    std::string example;                    // a value for documentation excerpts ("(1 0 0)"), when given
    std::optional<KeywordBound> lower, upper;
    bool orEnclosing = false;
    // A sub-dictionary's own schema (KeywordSchema::nested): read() validates the sub-dictionary
    // through it when given; listings and mfDoc show its keywords indented under this one.
    KeywordSchema (*nested)() = nullptr;

    // "a real number", "one of cubic | linearUsUp", "a switch (yes/no)", ...
    std::string typeText() const;
    // "> 0", ">= 0 and <= 1", "" when unbounded.
    std::string boundsText() const;
    // "required", "default 7", "optional"
    std::string kindText() const;
    // An example value for a dictionary excerpt: the default, else the declared example, else a
    // value inside the bounds.
    std::string sampleValue() const;
};

// The shortest text that reads back as `value` ("2.65e+08", "0.9", "293.15").
std::string formatKeywordNumber(double value);

class KeywordSchema {
public:
    KeywordSchema() = default;
    KeywordSchema(std::string family, std::string type)
        : family_(std::move(family)), type_(std::move(type)) {}

    // Declarations; a keyword is required until one of orDefault()/optional() says otherwise.
    KeywordSchema& scalar(std::string name, std::string unit, std::string meaning);
    KeywordSchema& integer(std::string name, std::string unit, std::string meaning);
    KeywordSchema& word(std::string name, std::vector<std::string> words, std::string meaning);
    KeywordSchema& vector(std::string name, std::string unit, std::string meaning);
    KeywordSchema& flag(std::string name, std::string meaning);  // a switch: yes/no, on/off, true/false
    KeywordSchema& dictionary(std::string name, std::string meaning);
    KeywordSchema& words(std::string name, std::string meaning);       // a non-empty list of names
    KeywordSchema& identifier(std::string name, std::string meaning);  // one name, any
    KeywordSchema& table(std::string name, std::string unit, std::string meaning);

    // Modifiers of the keyword declared last.
    KeywordSchema& orDefault(double value);
    KeywordSchema& orDefault(int value);
    KeywordSchema& orDefault(bool value);
    KeywordSchema& orDefault(const char* value);
    KeywordSchema& orDefault(const std::string& value);
    KeywordSchema& orDefault(const std::vector<double>& value);            // a vector: written "(1 2)"
    KeywordSchema& orDefaultNames(const std::vector<std::string>& value);  // a list of names
    KeywordSchema& optional();
    KeywordSchema& greaterThan(double bound);
    KeywordSchema& atLeast(double bound);
    KeywordSchema& lessThan(double bound);
    KeywordSchema& atMost(double bound);
    KeywordSchema& orEnclosing();
    KeywordSchema& ofLength(std::size_t components);  // a vector of exactly this many values
    // The value a documentation excerpt shows, where the default rule (zeros, the lower bound)
    // would show an invalid one: a plane's normal "(1 0 0)".
    KeywordSchema& example(std::string value);
    // The schema of the sub-dictionary declared last (a `dictionary` keyword):
    //     .dictionary("projection", "...").optional().nested(&TlSphSolver<3>::projectionKeywords)
    // read() reads a given sub-dictionary through it (errors at the sub-dictionary's file and
    // line, its defaults echoed), and KeywordValues::nested(name) returns those values; an
    // absent optional sub-dictionary is not read (check given(name) first).
    KeywordSchema& nested(KeywordSchema (*schema)());

    // The keywords of `other` (a base model's), after those declared so far.
    KeywordSchema& append(const KeywordSchema& other);
    // Declared as another model (a derived type reusing its base's schema).
    KeywordSchema& rename(std::string family, std::string type);

    const std::string& family() const { return family_; }
    const std::string& type() const { return type_; }
    // A reference into this schema: keep the schema itself alive while iterating (a range-for over
    // `item.keywords().keywords()` would dangle).
    const std::vector<Keyword>& keywords() const { return keywords_; }
    const Keyword* find(std::string_view name) const;
    bool empty() const { return keywords_.empty(); }

    // Validate `dict` and return the values; see the header comment.
    KeywordValues read(const Dictionary& dict) const;

    // Text for -listModels: one line per keyword, "name  unit  required|default x  bounds".
    std::string summary(const std::string& indent) const;

private:
    Keyword& last(const char* modifier);

    std::string family_, type_;
    std::vector<Keyword> keywords_;
};

// The values of one construction, by keyword name.
class KeywordValues {
public:
    double scalar(std::string_view name) const;
    std::optional<double> optionalScalar(std::string_view name) const;
    long integer(std::string_view name) const;
    const std::string& word(std::string_view name) const;  // a word or an identifier
    bool flag(std::string_view name) const;
    const std::vector<double>& vector(std::string_view name) const;
    const Dictionary& dictionary(std::string_view name) const;
    // The values of a sub-dictionary declared with a nested schema; std::logic_error when it has
    // none or the sub-dictionary was not given.
    const KeywordValues& nested(std::string_view name) const;
    const std::vector<std::string>& words(std::string_view name) const;  // empty when not given
    // True when the keyword was given (in the model's or, for orEnclosing, the enclosing dictionary).
    bool given(std::string_view name) const;
    // An InputError located at the entry `name` in whichever dictionary holds it (for checks
    // across keywords: Ecv > Eiv, B or c0 but not both).
    InputError error(std::string_view name, const std::string& message) const;
    // "hugoniot cubic", one per default applied.
    const std::vector<std::string>& defaultsUsed() const { return defaultsUsed_; }
    const Dictionary& dict() const { return *dict_; }

private:
    friend class KeywordSchema;
    struct Value {
        Keyword keyword;
        const Dictionary* holder = nullptr;  // null: not given
        double number = 0.0;
        long integer = 0;
        bool flag = false;
        std::string text;
        std::vector<double> list;
        std::vector<std::string> names;
        std::shared_ptr<const KeywordValues> nested;  // the sub-dictionary's values (Keyword::nested)
    };
    const Value& value(std::string_view name, Keyword::Type type) const;

    const Dictionary* dict_ = nullptr;
    std::vector<Value> values_;
    std::vector<std::string> defaultsUsed_;
    std::string model_;
};

}  // namespace mfdyn
