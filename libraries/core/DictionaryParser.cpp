// The dictionary grammar (Boost.Spirit X3) and the builder that turns its syntax tree into
// Dictionary entries. This is the only translation unit that includes X3, so the rest of the
// toolkit compiles without it.
//
// Two passes: the grammar produces an AST with byte offsets and nothing else (no file access, no
// macro look-up); the builder then walks it in order, reading #include files and expanding
// $macros against the entries defined so far. Errors of the first pass come from X3 expectation
// points; the grammar is LL(1) (the first character decides every alternative), so the semantic
// actions that grow the AST never run on a branch that is later abandoned.
#include "core/Dictionary.hpp"
#include "core/MessageText.hpp"

#include <algorithm>
#include <boost/spirit/home/x3.hpp>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace mfdyn {

namespace {

namespace x3 = boost::spirit::x3;
namespace fs = std::filesystem;

// ------------------------------------------------------------------------------------------
// Syntax tree

struct AstDict;

struct AstToken {
    enum class Kind { integer, real, word, string, macro, list, dict };
    Kind kind = Kind::word;
    std::string text;  // spelling of a number, word, decoded string, or macro name
    std::size_t begin = 0, end = 0;
    std::vector<AstToken> list;
    std::unique_ptr<AstDict> dict;
};

struct AstStatement {
    enum class Kind { entry, dictEntry, include, includeEtc, macroMerge };
    Kind kind = Kind::entry;
    std::string key;  // the key, or the macro name of a `$name;` entry
    std::size_t begin = 0, end = 0;
    std::vector<AstToken> tokens;  // the value, or the file name of a directive
    std::unique_ptr<AstDict> dict;
    std::size_t valueBegin = 0, valueEnd = 0;
};

struct AstDict {
    std::vector<AstStatement> statements;
    std::size_t open = 0, close = 0;  // '{' and '}' (0 and end of text for a file)
};

// Too deep a nesting would exhaust the stack of the recursive-descent parser long before memory.
// The builder applies the same limit across included files and $macro values, whose copies and
// printing recurse as deep.
constexpr std::size_t maxNesting = 200;

// Each #include is a level of the builder's recursion, with the included file's text and syntax
// tree held until it is done: a chain of 12 800 files overflowed the stack. Real cases include a
// few files deep.
constexpr std::size_t maxIncludeDepth = 64;

// The values (tokens and entries) that $macro expansion may copy in one read, included files
// counted. `b ($a $a); c ($b $b); ...` doubles at every line: 40 lines would copy 2^40 values
// (a hang, then std::bad_alloc). A million is far more than a case copies (a table of 10^5 rows
// of a time and a vector, used twice, is 10^6) and costs a few hundred MB at most.
constexpr std::size_t maxMacroValues = 1000000;

struct NestingTooDeep {
    std::size_t offset;
};

// What the actions need: where the text starts, and the innermost open constructs. The `open`
// stack also names, in error messages, the dictionary or list left unclosed.
struct ParseState {
    const char* base = nullptr;
    std::vector<AstDict*> dicts;
    std::vector<AstStatement*> statements;
    std::vector<std::vector<AstToken>*> tokenLists;
    struct Open {
        char kind;  // '{' dictionary entry, 't' dictionary in a list, '(' list, 'k' value of an entry
        std::size_t offset;
        std::string key;
    };
    std::vector<Open> open;

    void push(char kind, std::size_t offset, std::string key) {
        if (open.size() >= maxNesting) throw NestingTooDeep{offset};
        open.push_back({kind, offset, std::move(key)});
    }
};

struct StateTag;

template <class Context>
ParseState& stateOf(const Context& ctx) {
    return *x3::get<StateTag>(ctx);
}

// ------------------------------------------------------------------------------------------
// Character classes. Our own, because <cctype> is undefined for the negative chars of UTF-8 bytes.

constexpr bool isSpace(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
constexpr bool isDigit(unsigned char c) {
    return c >= '0' && c <= '9';
}
// Anything printable that does not delimit tokens; UTF-8 bytes are allowed in words.
constexpr bool isWordByte(unsigned char c) {
    if (c <= ' ' || c == 127) return false;
    switch (c) {
        case '"':
        case ';':
        case '{':
        case '}':
        case '(':
        case ')':
        case '$':
        case '#':
            return false;
        default:
            return true;
    }
}

// One word character; a '/' only when it does not start a comment.
struct WordChar : x3::parser<WordChar> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    bool allowDigit = true;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        x3::skip_over(first, last, ctx);
        if (first == last) return false;
        const auto c = static_cast<unsigned char>(*first);
        if (!isWordByte(c) || (!allowDigit && isDigit(c))) return false;
        if (c == '/' && std::next(first) != last && (*std::next(first) == '/' || *std::next(first) == '*'))
            return false;
        ++first;
        return true;
    }
};

struct DigitChar : x3::parser<DigitChar> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        x3::skip_over(first, last, ctx);
        if (first == last || !isDigit(static_cast<unsigned char>(*first))) return false;
        ++first;
        return true;
    }
};

// A character allowed inside "...": not the quote, not a backslash, not a line end (a string
// that runs to the end of the line is reported there rather than at the end of the file).
struct StringChar : x3::parser<StringChar> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx&, RCtx&, Attr&) const {
        if (first == last) return false;
        const char c = *first;
        if (c == '"' || c == '\\' || c == '\n' || c == '\r') return false;
        ++first;
        return true;
    }
};

// The character after a backslash: anything on the same line.
struct EscapedChar : x3::parser<EscapedChar> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx&, RCtx&, Attr&) const {
        if (first == last || *first == '\n' || *first == '\r') return false;
        ++first;
        return true;
    }
};

// White space and comments. An unterminated `/*` is an expectation failure located at the
// comment's opening, which is where the user has to look.
struct Blank : x3::parser<Blank> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx&, RCtx&, Attr&) const {
        const It start = first;
        while (first != last) {
            if (isSpace(static_cast<unsigned char>(*first))) {
                ++first;
            } else if (*first == '/' && std::next(first) != last && *std::next(first) == '/') {
                while (first != last && *first != '\n') ++first;
            } else if (*first == '/' && std::next(first) != last && *std::next(first) == '*') {
                const It open = first;
                first += 2;
                for (;;) {
                    if (first == last || std::next(first) == last)
                        boost::throw_exception(x3::expectation_failure<It>(open, "end of comment"));
                    if (*first == '*' && *std::next(first) == '/') break;
                    ++first;
                }
                first += 2;
            } else {
                break;
            }
        }
        return first != start;
    }
};

const WordChar wordChar{};
const WordChar wordStart{{}, false};
const DigitChar digit{};
const StringChar stringChar{};
const EscapedChar escapedChar{};

using Range = boost::iterator_range<const char*>;

template <class Ctx>
std::size_t beginOf(const Ctx& ctx) {
    return std::size_t(x3::_attr(ctx).begin() - stateOf(ctx).base);
}
template <class Ctx>
std::size_t endOf(const Ctx& ctx) {
    return std::size_t(x3::_attr(ctx).end() - stateOf(ctx).base);
}
template <class Ctx>
std::string textOf(const Ctx& ctx) {
    return std::string(x3::_attr(ctx).begin(), x3::_attr(ctx).end());
}

// `"..."` to its contents: only \" and \\ are escapes; any other backslash stays as written.
std::string unquote(const char* begin, const char* end) {
    std::string s;
    s.reserve(std::size_t(end - begin));
    for (const char* p = begin + 1; p + 1 < end; ++p) {
        if (*p == '\\' && p + 2 < end && (p[1] == '"' || p[1] == '\\')) ++p;
        s += *p;
    }
    return s;
}

// ------------------------------------------------------------------------------------------
// Semantic actions

AstToken& pushToken(ParseState& st, AstToken::Kind kind, std::size_t begin, std::size_t end,
                    std::string text) {
    auto& list = *st.tokenLists.back();
    list.push_back(AstToken{kind, std::move(text), begin, end, {}, {}});
    return list.back();
}

const auto onNumber = [](auto& ctx) {
    auto& st = stateOf(ctx);
    std::string text = textOf(ctx);
    const bool integer = text.find_first_of(".eE") == std::string::npos;
    pushToken(st, integer ? AstToken::Kind::integer : AstToken::Kind::real, beginOf(ctx), endOf(ctx),
              std::move(text));
};
const auto onWord = [](auto& ctx) {
    pushToken(stateOf(ctx), AstToken::Kind::word, beginOf(ctx), endOf(ctx), textOf(ctx));
};
const auto onString = [](auto& ctx) {
    pushToken(stateOf(ctx), AstToken::Kind::string, beginOf(ctx), endOf(ctx),
              unquote(x3::_attr(ctx).begin(), x3::_attr(ctx).end()));
};
const auto onMacro = [](auto& ctx) {
    pushToken(stateOf(ctx), AstToken::Kind::macro, beginOf(ctx), endOf(ctx), textOf(ctx).substr(1));
};
const auto onListOpen = [](auto& ctx) {
    auto& st = stateOf(ctx);
    st.push('(', beginOf(ctx), {});
    AstToken& t = pushToken(st, AstToken::Kind::list, beginOf(ctx), 0, {});
    st.tokenLists.push_back(&t.list);
};
const auto onListClose = [](auto& ctx) {
    auto& st = stateOf(ctx);
    st.tokenLists.pop_back();
    st.tokenLists.back()->back().end = endOf(ctx);
    st.open.pop_back();
};
const auto onDictTokenOpen = [](auto& ctx) {
    auto& st = stateOf(ctx);
    st.push('t', beginOf(ctx), {});
    AstToken& t = pushToken(st, AstToken::Kind::dict, beginOf(ctx), 0, {});
    t.dict = std::make_unique<AstDict>();
    t.dict->open = beginOf(ctx);
    st.dicts.push_back(t.dict.get());
    st.tokenLists.push_back(nullptr);  // a dictionary's statements own their token lists
};
// Closes a dictionary entry's or a dictionary token's braces.
const auto onDictClose = [](auto& ctx) {
    auto& st = stateOf(ctx);
    st.dicts.back()->close = beginOf(ctx);
    st.dicts.pop_back();
    const bool isToken = st.open.back().kind == 't';
    st.open.pop_back();
    if (isToken) {
        st.tokenLists.pop_back();
        st.tokenLists.back()->back().end = endOf(ctx);
    } else {
        AstStatement& s = *st.statements.back();
        s.valueBegin = s.dict->open + 1;
        s.valueEnd = s.dict->close;
        st.statements.pop_back();
    }
};
AstStatement& pushStatement(ParseState& st, AstStatement::Kind kind, std::size_t begin, std::size_t end,
                            std::string key) {
    auto& statements = st.dicts.back()->statements;
    statements.push_back(AstStatement{kind, std::move(key), begin, end, {}, {}, 0, 0});
    st.statements.push_back(&statements.back());
    return statements.back();
}
const auto onKeyWord = [](auto& ctx) {
    pushStatement(stateOf(ctx), AstStatement::Kind::entry, beginOf(ctx), endOf(ctx), textOf(ctx));
};
const auto onKeyString = [](auto& ctx) {
    pushStatement(stateOf(ctx), AstStatement::Kind::entry, beginOf(ctx), endOf(ctx),
                  unquote(x3::_attr(ctx).begin(), x3::_attr(ctx).end()));
};
const auto onEntryDictOpen = [](auto& ctx) {
    auto& st = stateOf(ctx);
    AstStatement& s = *st.statements.back();
    st.push('{', beginOf(ctx), s.key);
    s.kind = AstStatement::Kind::dictEntry;
    s.dict = std::make_unique<AstDict>();
    s.dict->open = beginOf(ctx);
    st.dicts.push_back(s.dict.get());
};
const auto onValueBegin = [](auto& ctx) {
    auto& st = stateOf(ctx);
    AstStatement& s = *st.statements.back();
    st.push('k', s.begin, s.key);
    st.tokenLists.push_back(&s.tokens);
};
const auto onValueEnd = [](auto& ctx) {
    auto& st = stateOf(ctx);
    AstStatement& s = *st.statements.back();
    if (s.tokens.empty()) {
        s.valueBegin = s.valueEnd = beginOf(ctx);
    } else {
        s.valueBegin = s.tokens.front().begin;
        s.valueEnd = s.tokens.back().end;
    }
    st.tokenLists.pop_back();
    st.statements.pop_back();
    st.open.pop_back();
};
const auto onHash = [](auto& ctx) {
    auto& st = stateOf(ctx);
    AstStatement& s = pushStatement(st, AstStatement::Kind::include, beginOf(ctx), endOf(ctx), {});
    st.tokenLists.push_back(&s.tokens);
};
const auto onIncludeEtc = [](auto& ctx) {
    stateOf(ctx).statements.back()->kind = AstStatement::Kind::includeEtc;
};
const auto onDirectiveEnd = [](auto& ctx) {
    auto& st = stateOf(ctx);
    st.tokenLists.pop_back();
    st.statements.pop_back();
};
const auto onMacroEntry = [](auto& ctx) {
    auto& st = stateOf(ctx);
    pushStatement(st, AstStatement::Kind::macroMerge, beginOf(ctx), endOf(ctx), textOf(ctx).substr(1));
    st.statements.pop_back();
};

// ------------------------------------------------------------------------------------------
// Grammar. The rule names are what expectation failures report; describeFailure() below turns
// them into sentences.

const auto closeQuote = x3::rule<class CloseQuote>{"'\"'"} = x3::lit('"');
const auto quoted = x3::lexeme['"' >> *(('\\' >> escapedChar) | stringChar) > closeQuote];
const auto wordText = x3::lexeme[wordStart >> *wordChar];

const x3::rule<class Exponent> exponent = "exponent";
const x3::rule<class NumberEnd> numberEnd = "number end";
const x3::rule<class Number> number = "number";
const x3::rule<class Word> word = "word";
const x3::rule<class StringToken> stringToken = "string";
const x3::rule<class MacroName> macroName = "a macro name";
const x3::rule<class Macro> macro = "macro";
const x3::rule<class ListToken> listToken = "list";
const x3::rule<class CloseParen> closeParen = "')'";
const x3::rule<class DictToken> dictToken = "dictionary";
const x3::rule<class CloseBrace> closeBrace = "'}'";
const x3::rule<class Token> token = "a value";
const x3::rule<class Semicolon> semicolon = "';'";
const x3::rule<class Key> key = "a keyword";
const x3::rule<class DictValue> dictValue = "dictionary value";
const x3::rule<class PrimitiveValue> primitiveValue = "value";
const x3::rule<class EntryRule> entry = "entry";
const x3::rule<class DirectiveName> directiveName = "a directive";
const x3::rule<class IncludeFile> includeFile = "a quoted file name";
const x3::rule<class Directive> directive = "directive";
const x3::rule<class MacroEntry> macroEntry = "macro entry";
const x3::rule<class Statement> statement = "statement";
const x3::rule<class Body> body = "body";
const x3::rule<class EndOfInput> endOfInput = "end of input";
const x3::rule<class File> file = "file";

const auto sign = x3::lit('+') | x3::lit('-');
const auto mantissa = (+digit >> -('.' >> *digit)) | ('.' >> +digit);

const auto exponent_def = -sign >> +digit;
const auto numberEnd_def = x3::no_skip[!wordChar];
const auto number_def =
    x3::raw[x3::lexeme[-sign >> mantissa >> -((x3::lit('e') | x3::lit('E')) > exponent)]][onNumber] >
    numberEnd;
const auto word_def = x3::raw[wordText][onWord];
const auto stringToken_def = x3::raw[quoted][onString];
const auto macroName_def = x3::lexeme[+wordChar];
const auto macro_def = x3::raw[x3::lexeme['$' > macroName]][onMacro];
const auto closeParen_def = x3::raw[x3::lit(')')][onListClose];
const auto listToken_def = x3::raw[x3::lit('(')][onListOpen] >> *(token | dictToken) > closeParen;
const auto closeBrace_def = x3::raw[x3::lit('}')][onDictClose];
const auto dictToken_def = x3::raw[x3::lit('{')][onDictTokenOpen] >> body > closeBrace;
const auto token_def = number | stringToken | macro | listToken | word;
const auto semicolon_def = x3::raw[x3::lit(';')][onValueEnd];
const auto key_def = x3::raw[wordText][onKeyWord] | x3::raw[quoted][onKeyString];
const auto dictValue_def = (x3::raw[x3::lit('{')][onEntryDictOpen] >> body > closeBrace) >> -x3::lit(';');
const auto primitiveValue_def = x3::eps[onValueBegin] >> *token > semicolon;
const auto entry_def = key >> (dictValue | primitiveValue);
const auto directiveName_def =
    x3::lexeme[(x3::lit("includeEtc") >> !wordChar)[onIncludeEtc] | (x3::lit("include") >> !wordChar)];
const auto includeFile_def = stringToken;
const auto directive_def = x3::lexeme[x3::raw[x3::lit('#')][onHash] > directiveName] > includeFile >
                           x3::eps[onDirectiveEnd] >> -x3::lit(';');
const auto macroEntry_def = x3::raw[x3::lexeme['$' > macroName]][onMacroEntry] >> -x3::lit(';');
const auto statement_def = directive | macroEntry | entry;
const auto body_def = *statement;
const auto endOfInput_def = x3::eoi;
const auto file_def = body > endOfInput;

BOOST_SPIRIT_DEFINE(exponent, numberEnd, number, word, stringToken, macroName, macro, listToken, closeParen,
                    dictToken, closeBrace, token, semicolon, key, dictValue, primitiveValue, entry,
                    directiveName, includeFile, directive, macroEntry, statement, body, endOfInput, file)

// ------------------------------------------------------------------------------------------
// Locations and messages

struct Source {
    std::shared_ptr<const std::string> name;
    std::string text;
    fs::path directory;  // base of relative #include
    std::vector<std::size_t> lineStarts;

    Source(std::string fileName, std::string contents)
        : name(std::make_shared<const std::string>(std::move(fileName))), text(std::move(contents)) {
        directory = fs::path(*name).parent_path();
        lineStarts.push_back(0);
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') lineStarts.push_back(i + 1);
    }

    SourceLocation at(std::size_t offset) const {
        const auto it = std::upper_bound(lineStarts.begin(), lineStarts.end(), offset);
        const std::size_t line = std::size_t(it - lineStarts.begin());
        return SourceLocation{name, int(line), int(offset - lineStarts[line - 1] + 1)};
    }
    std::string lineColumn(std::size_t offset) const {
        const SourceLocation l = at(offset);
        return std::to_string(l.line) + ":" + std::to_string(l.column);
    }
};

// "end of input", "';'", "'foo'": what stands at `offset`, for "found ..." in messages.
std::string foundAt(const std::string& text, std::size_t offset) {
    if (offset >= text.size()) return "end of input";
    const auto c = static_cast<unsigned char>(text[offset]);
    if (!isWordByte(c) || c == '/') {
        if (c == '\n' || c == '\r') return "end of line";
        if (c < ' ' || c >= 127) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "0x%02x", unsigned(c));
            return std::string("byte ") + buf;
        }
        return std::string("'") + char(c) + "'";
    }
    std::size_t end = offset;
    while (end < text.size() && isWordByte(static_cast<unsigned char>(text[end])) && end - offset <= 40)
        ++end;
    return "'" + excerpt(std::string_view(text).substr(offset, end - offset), 40) + "'";
}

[[noreturn]] void fail(const Source& src, std::size_t offset, const std::string& message) {
    throw InputError(src.at(offset), "", message);
}

// Turns an expectation failure into "expected X ..., found Y", located where the problem is.
// The offset of the next token after `offset`: X3 reports a failure before skipping blanks.
std::size_t skipBlanks(const std::string& text, std::size_t offset) {
    while (offset < text.size()) {
        if (isSpace(static_cast<unsigned char>(text[offset]))) {
            ++offset;
        } else if (text.compare(offset, 2, "//") == 0) {
            while (offset < text.size() && text[offset] != '\n') ++offset;
        } else if (text.compare(offset, 2, "/*") == 0) {
            const std::size_t close = text.find("*/", offset + 2);
            if (close == std::string::npos) break;
            offset = close + 2;
        } else {
            break;
        }
    }
    return offset;
}

[[noreturn]] void describeFailure(const Source& src, const ParseState& st, std::size_t where,
                                  const std::string& which) {
    const std::string& text = src.text;
    // A missing ';' is reported right after the value it should end, the rest at the next token.
    const std::size_t next = skipBlanks(text, where);
    if (which != "end of comment" && which != "'\"'" && which != "exponent" && which != "number end" &&
        which != "';'")
        where = next;
    const std::string found = foundAt(text, which == "';'" ? next : where);
    const char at = next < text.size() ? text[next] : '\0';
    const ParseState::Open* inner = st.open.empty() ? nullptr : &st.open.back();

    if (which == "end of comment") fail(src, where, "unterminated comment: '/*' is never closed by '*/'");
    if (which == "'\"'") fail(src, where, "unterminated string: expected '\"' before the " + found);
    if (which == "exponent" || which == "number end") {
        std::size_t b = where, e = where;
        while (b > 0 && isWordByte(static_cast<unsigned char>(text[b - 1]))) --b;
        while (e < text.size() && isWordByte(static_cast<unsigned char>(text[e]))) ++e;
        const std::string spelling = excerpt(std::string_view(text).substr(b, e - b), 40);
        fail(src, b,
             "bad number '" + spelling + "': " +
                 (which == "exponent" ? std::string("expected digits after the exponent")
                                      : "expected a number such as 12, -0.5 or 1.5e-3"));
    }
    if (which == "a macro name") fail(src, where, "expected a macro name after '$', found " + found);
    if (which == "a directive") {
        std::size_t e = where;
        while (e < text.size() && isWordByte(static_cast<unsigned char>(text[e]))) ++e;
        fail(src, where - 1,
             "unknown directive '#" + excerpt(std::string_view(text).substr(where, e - where), 40) +
                 "': expected #include or #includeEtc");
    }
    if (which == "a quoted file name")
        fail(src, where, "expected a quoted file name after the directive, found " + found);
    if (at == ';' && (which == "'}'" || which == "end of input"))
        fail(src, where, "expected a keyword before ';' (empty keyword)");
    if (which == "';'") {
        const std::string key = inner ? excerpt(inner->key) : std::string();
        fail(src, where, "expected ';' after the value of '" + key + "', found " + found);
    }
    if (which == "')'") {
        fail(src, where,
             "expected ')' to close the list opened at " + src.lineColumn(inner ? inner->offset : 0) +
                 ", found " + found);
    }
    if (which == "'}'") {
        const std::string what = inner && !inner->key.empty() ? "dictionary '" + excerpt(inner->key) + "'"
                                                              : std::string("dictionary");
        const std::string opened = src.lineColumn(inner ? inner->offset : 0);
        if (where >= text.size())
            fail(src, where,
                 "expected '}' to close " + what + " opened at " + opened + ", found end of input");
        fail(src, where,
             "expected a keyword or '}' to close " + what + " opened at " + opened + ", found " + found);
    }
    if (which == "end of input") {
        if (at == '}') fail(src, where, "unmatched '}' with no '{' before it");
        fail(src, where, "expected a keyword, found " + found);
    }
    fail(src, where, "expected " + which + ", found " + found);
}

std::unique_ptr<AstDict> parseSyntax(const Source& src) {
    auto root = std::make_unique<AstDict>();
    root->close = src.text.size();
    ParseState st;
    st.base = src.text.data();
    st.dicts.push_back(root.get());
    const char* first = src.text.data();
    const char* const last = first + src.text.size();
    try {
        const bool ok = x3::phrase_parse(first, last, x3::with<StateTag>(&st)[file], Blank{});
        if (!ok) fail(src, std::size_t(first - st.base), "cannot parse this");
    } catch (const x3::expectation_failure<const char*>& e) {
        describeFailure(src, st, std::size_t(e.where() - st.base), e.which());
    } catch (const NestingTooDeep& e) {
        fail(src, e.offset, "nesting deeper than " + std::to_string(maxNesting) + " levels");
    }
    return root;
}

// ------------------------------------------------------------------------------------------
// Builder: AST to Dictionary, with includes and macros expanded in order.

// Larger than any dictionary: a file this size is not one (a particle file or a disk image named
// by mistake), and reading it whole would end in std::bad_alloc rather than a message.
constexpr std::uintmax_t maxFileBytes = std::uintmax_t(1) << 30;

std::string readFile(const fs::path& path) {
    std::error_code ec;
    const std::uintmax_t bytes = fs::file_size(path, ec);
    if (!ec && bytes > maxFileBytes)
        throw InputError("file '" + excerpt(path.string(), 200) + "' is " + std::to_string(bytes) +
                         " bytes, more than the " + std::to_string(maxFileBytes) +
                         " a dictionary may have: is it a dictionary?");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot open file '" + excerpt(path.string(), 200) + "'");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string joinScope(const std::string& scope, const std::string& key) {
    return scope.empty() ? key : scope + "/" + key;
}

fs::path canonicalOrSame(const fs::path& p) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(p, ec);
    return ec ? p : c;
}

// True when `path` names `root` or something below it (both canonical).
bool isInside(const fs::path& path, const fs::path& root) {
    const fs::path rel = path.lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}

// The number `a` as written, read by std::from_chars: no locale, no exception. A value beyond the
// range of a double is an error, not inf or 0, which would pass on a number the user did not write
// (1e999 as inf, 1e-400 as 0, both of which bounds such as "> 0" then judge wrongly). Subnormal
// values (5e-321) are doubles like any other and read as their value: refusing them would refuse
// valid input, and the digits kept are the nearest a double holds, as for every other number.
double readReal(const Source& src, const AstToken& a) {
    const char* b = a.text.data();
    const char* const e = b + a.text.size();
    if (b != e && *b == '+') ++b;  // from_chars takes no '+'
    double v = 0.0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec == std::errc::result_out_of_range)
        fail(src, a.begin,
             "number '" + excerpt(a.text, 40) +
                 "' is out of range: a real must lie between about 4.9e-324 and 1.8e+308 in magnitude, or be "
                 "0");
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v))
        fail(src, a.begin, "bad number '" + excerpt(a.text, 40) + "'");
    return v;
}

class Builder {
public:
    explicit Builder(const ReadOptions& options) : options_(options) {}

    void buildFile(const Source& src, Dictionary& target, bool included) {
        const auto ast = parseSyntax(src);
        buildStatements(src, *ast, target, included);
    }

    // The file Dictionary::parse reads, the first link of the include chain (so that a file that
    // includes itself is a loop).
    void openTopLevel(const std::string& fileName) {
        if (fileName.empty()) return;
        const fs::path canonical = canonicalOrSame(fileName);
        chain_.push_back({canonical, {}});
        open_.insert(canonical);
    }

    void buildStatements(const Source& src, const AstDict& ast, Dictionary& dict, bool included) {
        std::map<std::string, SourceLocation, std::less<>> literal;  // keys written in this block
        for (const AstStatement& s : ast.statements) {
            switch (s.kind) {
                case AstStatement::Kind::entry:
                case AstStatement::Kind::dictEntry: {
                    if (s.key.empty()) fail(src, s.begin, "empty keyword");
                    const SourceLocation where = src.at(s.begin);
                    if (auto it = literal.find(s.key); it != literal.end()) {
                        fail(src, s.begin,
                             "duplicate keyword '" + excerpt(s.key) + "': first defined at " +
                                 it->second.str());
                    }
                    literal.emplace(s.key, where);
                    auto e = std::make_unique<Entry>();
                    e->key = s.key;
                    e->where = where;
                    e->fromInclude = included;
                    e->valueBegin = s.valueBegin;
                    e->valueEnd = s.valueEnd;
                    if (s.kind == AstStatement::Kind::dictEntry) {
                        e->dict = makeDict(src, *s.dict, dict, s.key, where, included);
                    } else {
                        {
                            const Deeper value(*this, src, s.begin);  // the grammar's level of a value
                            e->tokens = expand(src, s.tokens, dict, s.key, true);
                        }
                        // `b $a;` with `a` a dictionary makes `b` a dictionary too.
                        if (e->tokens.size() == 1 && e->tokens.front().kind == Token::Kind::dictionary &&
                            s.tokens.size() == 1 && s.tokens.front().kind == AstToken::Kind::macro) {
                            // The token's copy is its own: moved, not copied again.
                            e->dict = std::make_unique<Dictionary>(std::move(*e->tokens.front().dict));
                            e->dict->setWhere(where);
                            e->dict->closeBraceOffset = std::string::npos;  // no braces of its own to edit
                            e->tokens.clear();
                        }
                    }
                    insert(dict, std::move(e));
                    break;
                }
                case AstStatement::Kind::include:
                case AstStatement::Kind::includeEtc:
                    include(src, s, dict);
                    break;
                case AstStatement::Kind::macroMerge: {
                    const Entry* ref = findMacro(src, s.key, s.begin, dict);
                    if (!ref->isDict())
                        fail(src, s.begin,
                             "'$" + excerpt(s.key) + "' is not a dictionary, so it cannot stand as an entry");
                    chargeMacro(src, s.begin, s.key, *ref, true);
                    for (const auto& sub : ref->dict->entries()) {
                        auto copy = sub->clone();
                        copy->fromInclude = true;
                        insert(dict, std::move(copy));
                    }
                    break;
                }
            }
        }
    }

private:
    // One level deeper (a dictionary or a list), for as long as it lives; refused beyond maxNesting.
    class Deeper {
    public:
        Deeper(Builder& builder, const Source& src, std::size_t at) : builder_(builder) {
            if (builder_.depth_ >= maxNesting)
                fail(src, at,
                     "nesting deeper than " + std::to_string(maxNesting) +
                         " levels (dictionaries and lists, counted through included files)");
            ++builder_.depth_;
        }
        ~Deeper() { --builder_.depth_; }
        Deeper(const Deeper&) = delete;
        Deeper& operator=(const Deeper&) = delete;

    private:
        Builder& builder_;
    };

    std::unique_ptr<Dictionary> makeDict(const Source& src, const AstDict& ast, const Dictionary& parent,
                                         const std::string& name, const SourceLocation& where,
                                         bool included) {
        const Deeper deeper(*this, src, ast.open);
        auto d = std::make_unique<Dictionary>();
        d->setScope(joinScope(parent.scope(), name), &parent);
        d->setWhere(where);
        d->closeBraceOffset = ast.close;
        buildStatements(src, ast, *d, included);
        return d;
    }

    // A later entry replaces an earlier one of the same key (literal duplicates were refused
    // before). Dictionaries merge, so that included defaults can be overridden one key at a time.
    static void insert(Dictionary& dict, std::unique_ptr<Entry> e) {
        const Entry* old = dict.peek(e->key);
        if (old && old->isDict() && e->isDict()) {
            Dictionary& target = *old->dict;
            for (const auto& sub : e->dict->entries()) insertMerged(target, sub->clone());
            target.setWhere(e->dict->where());
            target.closeBraceOffset = e->dict->closeBraceOffset;
            auto merged = std::make_unique<Entry>();
            merged->key = e->key;
            merged->where = e->where;
            merged->fromInclude = e->fromInclude;
            merged->valueBegin = e->valueBegin;
            merged->valueEnd = e->valueEnd;
            merged->dict = std::make_unique<Dictionary>(std::move(target));
            dict.addEntry(std::move(merged));
            return;
        }
        dict.addEntry(std::move(e));
    }
    static void insertMerged(Dictionary& dict, std::unique_ptr<Entry> e) { insert(dict, std::move(e)); }

    // The file an #includeEtc names, found only inside the etc directories: a name with a root
    // or a '..' component is refused before any look-up, and a file found is refused when its real
    // path (symbolic links followed) leaves the directory it was found in. Otherwise
    // `#includeEtc "../../../../etc/passwd"` read any file the user may read, and its first line
    // came back in the parse error.
    fs::path findEtc(const Source& src, std::size_t at, const std::string& name) const {
        const auto dirs = options_.etcDirectories.empty() ? etcDirectories() : options_.etcDirectories;
        std::string searched;
        for (const auto& d : dirs) searched += (searched.empty() ? "" : ", ") + excerpt(d.string(), 200);
        if (searched.empty()) searched = "any etc directory (none configured)";
        const std::string directive = "#includeEtc \"" + excerpt(name, 200) + "\"";
        const fs::path rel(name);
        if (name.empty())
            fail(src, at,
                 directive + ": expected the name of a file in the etc directories (" + searched + ")");
        if (rel.has_root_path())
            fail(src, at,
                 directive +
                     ": an absolute path; #includeEtc takes a name relative to the etc directories (" +
                     searched + "), #include takes any file");
        for (const auto& part : rel)
            if (part == "..")
                fail(src, at,
                     directive +
                         ": a '..' component; #includeEtc reads only files inside the etc directories (" +
                         searched + ")");
        for (const auto& d : dirs) {
            std::error_code ec;
            const fs::path candidate = d / rel;
            if (!fs::is_regular_file(candidate, ec)) continue;
            const fs::path real = canonicalOrSame(candidate);
            if (!isInside(real, canonicalOrSame(d)))
                fail(src, at,
                     directive + ": found as '" + excerpt(candidate.string(), 200) + "', which leads to '" +
                         excerpt(real.string(), 200) + "', outside the etc directory '" +
                         excerpt(d.string(), 200) + "'");
            return candidate;
        }
        fail(src, at, directive + ": not found in " + searched);
    }

    // "a:3 -> b:1 -> ... (58 more) -> c:1": where each open include was written, outermost first.
    std::string chainText() const {
        std::vector<std::string> links;
        for (const Link& l : chain_)
            if (l.includedAt.known())
                links.push_back(excerpt(*l.includedAt.file, 200) + ":" + std::to_string(l.includedAt.line));
        constexpr std::size_t head = 4, tail = 2;
        std::string s;
        for (std::size_t i = 0; i < links.size(); ++i) {
            if (i == head && links.size() > head + tail + 1) {
                s += " -> ... (" + std::to_string(links.size() - head - tail) + " more)";
                i = links.size() - tail - 1;
                continue;
            }
            s += (s.empty() ? "" : " -> ") + links[i];
        }
        return s;
    }

    void include(const Source& src, const AstStatement& s, Dictionary& dict) {
        const bool etc = s.kind == AstStatement::Kind::includeEtc;
        const std::string name = s.tokens.empty() ? std::string() : s.tokens.front().text;
        const std::size_t at = s.begin;
        fs::path path;
        if (etc) {
            path = findEtc(src, at, name);
        } else {
            path = fs::path(name);
            if (path.is_relative()) path = src.directory / path;
            std::error_code ec;
            if (!fs::is_regular_file(path, ec))
                fail(src, at,
                     "#include \"" + excerpt(name, 200) + "\": cannot open file '" +
                         excerpt(path.string(), 200) + "'");
        }
        const fs::path canonical = canonicalOrSame(path);
        if (open_.count(canonical)) {
            std::string loop;
            bool inLoop = false;
            for (const Link& l : chain_) {
                if (l.file == canonical) inLoop = true;
                if (inLoop) loop += excerpt(l.file.string(), 200) + " -> ";
            }
            fail(src, at, "include loop: " + loop + excerpt(canonical.string(), 200));
        }
        if (includeDepth_ >= maxIncludeDepth) {
            chain_.push_back({canonical, src.at(at)});  // this directive, the last link shown
            fail(src, at,
                 "included files nested deeper than " + std::to_string(maxIncludeDepth) +
                     " (an include chain that never ends?): " + chainText());
        }
        std::string text;
        try {
            text = readFile(path);
        } catch (const InputError& e) {
            fail(src, at, "cannot read included file '" + excerpt(path.string(), 200) + "': " + e.what());
        }
        chain_.push_back({canonical, src.at(at)});
        open_.insert(canonical);
        ++includeDepth_;
        const Source inner(path.string(), std::move(text));
        buildFile(inner, dict, true);
        --includeDepth_;
        open_.erase(canonical);
        chain_.pop_back();
    }

    static const Entry* lookupScoped(const Dictionary& start, std::string_view name) {
        for (const Dictionary* d = &start; d; d = d->parent())
            if (const Entry* e = d->peek(name)) return e;
        // `a.b.c` or `a/b/c`: the first component through the enclosing scopes, the rest below it.
        const std::size_t cut = name.find_first_of("./");
        if (cut == std::string_view::npos || cut == 0) return nullptr;
        const Entry* e = nullptr;
        for (const Dictionary* d = &start; d && !e; d = d->parent()) e = d->peek(name.substr(0, cut));
        std::string_view rest = name.substr(cut + 1);
        while (e) {
            if (!e->isDict()) return nullptr;
            const std::size_t next = rest.find_first_of("./");
            if (const Entry* whole = e->dict->peek(rest)) return whole;
            if (next == std::string_view::npos) return nullptr;
            e = e->dict->peek(rest.substr(0, next));
            rest = rest.substr(next + 1);
        }
        return nullptr;
    }

    const Entry* findMacro(const Source& src, const std::string& name, std::size_t at,
                           const Dictionary& dict) {
        const Dictionary* start = &dict;
        std::string_view n = name;
        if (!n.empty() && n.front() == ':') {  // `$:a.b` starts at the top level
            start = &dict.topLevel();
            n.remove_prefix(1);
        }
        const Entry* e = n.empty() ? nullptr : lookupScoped(*start, n);
        if (!e) {
            std::vector<std::string> visible;
            for (const Dictionary* d = start; d; d = d->parent())
                for (const auto& k : d->keys()) visible.push_back(k);
            const std::string guess = closestMatch(n, visible);
            fail(src, at,
                 "undefined macro '$" + excerpt(name) + "'" +
                     (guess.empty() ? std::string(" (only entries defined before it can be used)")
                                    : "; did you mean '$" + excerpt(guess) + "'?"));
        }
        e->read = true;  // a value used through a macro counts as used
        return e;
    }

    // What a value holds: its tokens and entries, all levels, and how many levels it opens below
    // the place it stands, counted as the grammar counts them: a list, a dictionary and the value
    // of an entry are one level each (so that whatever is read prints as text that reads again).
    struct Size {
        std::size_t values = 0, depth = 0;
        void add(const Size& inner, std::size_t levels) {
            values += inner.values;
            depth = std::max(depth, inner.depth + levels);
        }
    };
    static Size measure(const std::vector<Token>& tokens) {
        Size s;
        for (const Token& t : tokens) {
            ++s.values;
            if (t.kind == Token::Kind::list) s.add(measure(t.list), 1);
            if (t.dict) s.add(measureBody(*t.dict), 1);
        }
        return s;
    }
    static Size measureBody(const Dictionary& dict) {
        Size s;
        for (const auto& e : dict.entries()) {
            ++s.values;
            s.add(e->isDict() ? measureBody(*e->dict) : measure(e->tokens), 1);
        }
        return s;
    }

    // Counts the values a use of `$name` copies, and refuses the copy beyond maxMacroValues in
    // this read or beyond maxNesting levels at the place of use (each `b ($a)` nests one more).
    // `merged`: the entries of a dictionary `$name;` go into the current dictionary, not below it.
    void chargeMacro(const Source& src, std::size_t at, const std::string& name, const Entry& e,
                     bool merged) {
        const Size size = e.isDict() ? measureBody(*e.dict) : measure(e.tokens);
        const std::size_t reach = depth_ + size.depth + (e.isDict() && !merged ? 1 : 0);
        if (reach > maxNesting)
            fail(src, at,
                 "nesting deeper than " + std::to_string(maxNesting) + " levels: the value of '$" +
                     excerpt(name) + "' would reach " + std::to_string(reach) + " here");
        macroValues_ += size.values;
        if (macroValues_ > maxMacroValues)
            fail(
                src, at,
                "expanding '$" + excerpt(name) + "' (" + std::to_string(size.values) +
                    " values) takes the values copied by macros in this dictionary and its includes past the "
                    "limit of " +
                    std::to_string(maxMacroValues) +
                    " (does each macro repeat the one before, as in 'b ($a $a); c ($b $b);'?)");
    }

    // `inValue`: `in` are the tokens of an entry's value, not of a list inside it.
    std::vector<Token> expand(const Source& src, const std::vector<AstToken>& in, Dictionary& dict,
                              const std::string& key, bool inValue = false) {
        std::vector<Token> out;
        out.reserve(in.size());
        for (std::size_t i = 0; i < in.size(); ++i) {
            const AstToken& a = in[i];
            Token t;
            t.where = src.at(a.begin);
            switch (a.kind) {
                case AstToken::Kind::integer: {
                    t.kind = Token::Kind::integer;
                    t.text = a.text;
                    const char* b = a.text.data() + (a.text.front() == '+' ? 1 : 0);
                    const auto r = std::from_chars(b, a.text.data() + a.text.size(), t.integer);
                    if (r.ec != std::errc()) {  // too long for 64 bits: keep it as a real
                        t.kind = Token::Kind::real;
                        t.real = readReal(src, a);
                    } else {
                        t.real = double(t.integer);
                    }
                    break;
                }
                case AstToken::Kind::real:
                    t.kind = Token::Kind::real;
                    t.text = a.text;
                    t.real = readReal(src, a);
                    break;
                case AstToken::Kind::word:
                    t.kind = Token::Kind::word;
                    t.text = a.text;
                    break;
                case AstToken::Kind::string:
                    t.kind = Token::Kind::string;
                    t.text = a.text;
                    break;
                case AstToken::Kind::macro: {
                    const Entry* e = findMacro(src, a.text, a.begin, dict);
                    chargeMacro(src, a.begin, a.text, *e, false);
                    if (e->isDict()) {
                        // As in OpenFOAM, a dictionary macro stands for a whole entry (`b $a;`,
                        // `b { $a; }`) or an item of a list. Among other tokens of a value
                        // (`d $a 5;`) it made a value with no text: `d { ... } 5;` does not parse.
                        if (inValue && in.size() != 1)
                            fail(src, a.begin,
                                 "'$" + excerpt(a.text) +
                                     "' is a dictionary and cannot stand among the tokens of a value (use it "
                                     "alone, as in '" +
                                     excerpt(key) + " $" + excerpt(a.text) + ";', or inside a list)");
                        t.kind = Token::Kind::dictionary;
                        t.dict = std::make_shared<Dictionary>(*e->dict);
                        t.dict->closeBraceOffset = std::string::npos;
                        t.dict->setWhere(t.where);
                        break;
                    }
                    for (const Token& r : e->tokens) {
                        Token copy = r;
                        copy.where = t.where;
                        if (copy.dict) copy.dict = std::make_shared<Dictionary>(*copy.dict);
                        out.push_back(std::move(copy));
                    }
                    continue;
                }
                case AstToken::Kind::list: {
                    const Deeper deeper(*this, src, a.begin);
                    t.kind = Token::Kind::list;
                    t.list = expand(src, a.list, dict, key);
                    break;
                }
                case AstToken::Kind::dict:
                    t.kind = Token::Kind::dictionary;
                    t.dict =
                        makeDict(src, *a.dict, dict, key + "[" + std::to_string(i) + "]", t.where, false);
                    break;
            }
            out.push_back(std::move(t));
        }
        return out;
    }

    struct Link {
        fs::path file;              // canonical
        SourceLocation includedAt;  // the directive that opened it; unknown for the top-level file
    };
    const ReadOptions& options_;
    std::vector<Link> chain_;  // files being read, outermost first, for messages
    std::set<fs::path> open_;  // the same files, for the loop check (a scan of chain_ was quadratic)
    std::size_t includeDepth_ = 0;
    std::size_t depth_ = 0;        // dictionaries and lists open, across included files
    std::size_t macroValues_ = 0;  // values copied by $macro expansion so far
};

}  // namespace

Dictionary Dictionary::parse(std::string_view text, const std::string& fileName, const ReadOptions& options) {
    const Source src(fileName, std::string(text));
    Dictionary dict;
    dict.setWhere(src.at(0));
    dict.closeBraceOffset = text.size();
    Builder builder(options);
    builder.openTopLevel(fileName);
    builder.buildFile(src, dict, false);
    return dict;
}

Dictionary Dictionary::read(const std::filesystem::path& file, const ReadOptions& options) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))  // ec: the system's reason, e.g. a link to itself (ELOOP)
        throw InputError("cannot open dictionary file '" + excerpt(file.string(), 200) + "'" +
                         (ec ? ": " + ec.message() : std::string()));
    return parse(readFile(file), file.string(), options);
}

void Dictionary::set(std::string_view key, std::string_view valueText) {
    // The value is parsed as the body of `key value;` in this dictionary's scope, so its macros
    // see this dictionary's entries.
    std::string text(key);
    text += ' ';
    text += valueText;
    const bool isDict = valueText.find_first_not_of(" \t\r\n") != std::string_view::npos &&
                        valueText[valueText.find_first_not_of(" \t\r\n")] == '{';
    if (!isDict) text += "\n;";
    const Source src("value of '" + std::string(key) + "'", std::move(text));
    const auto ast = parseSyntax(src);
    if (ast->statements.size() != 1 || ast->statements.front().key != key)
        throw InputError(where_, name_, "cannot set '" + excerpt(key) + "' to '" + excerpt(valueText) + "'");
    Dictionary scratch;
    scratch.setScope(name_, this);
    ReadOptions options;
    Builder builder(options);
    builder.buildStatements(src, *ast, scratch, false);
    auto e = scratch.entries().front()->clone();
    e->read = false;
    addEntry(std::move(e));
}

}  // namespace mfdyn
