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

#include <algorithm>
#include <boost/spirit/home/x3.hpp>
#include <charconv>
#include <fstream>
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
constexpr std::size_t maxNesting = 200;

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
    while (end < text.size() && isWordByte(static_cast<unsigned char>(text[end])) && end - offset < 40) ++end;
    return "'" + text.substr(offset, end - offset) + "'";
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
        const std::string spelling = text.substr(b, e - b);
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
             "unknown directive '#" + text.substr(where, e - where) + "': expected #include or #includeEtc");
    }
    if (which == "a quoted file name")
        fail(src, where, "expected a quoted file name after the directive, found " + found);
    if (at == ';' && (which == "'}'" || which == "end of input"))
        fail(src, where, "expected a keyword before ';' (empty keyword)");
    if (which == "';'") {
        const std::string key = inner ? inner->key : std::string();
        fail(src, where, "expected ';' after the value of '" + key + "', found " + found);
    }
    if (which == "')'") {
        fail(src, where,
             "expected ')' to close the list opened at " + src.lineColumn(inner ? inner->offset : 0) +
                 ", found " + found);
    }
    if (which == "'}'") {
        const std::string what =
            inner && !inner->key.empty() ? "dictionary '" + inner->key + "'" : std::string("dictionary");
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

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot open file '" + path.string() + "'");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string joinScope(const std::string& scope, const std::string& key) {
    return scope.empty() ? key : scope + "/" + key;
}

class Builder {
public:
    explicit Builder(const ReadOptions& options) : options_(options) {}

    void buildFile(const Source& src, Dictionary& target, bool included) {
        const auto ast = parseSyntax(src);
        buildStatements(src, *ast, target, included);
    }

    std::vector<fs::path> chain;  // files being read, outermost first, for include loops

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
                             "duplicate keyword '" + s.key + "': first defined at " + it->second.str());
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
                        e->tokens = expand(src, s.tokens, dict, s.key);
                        // `b $a;` with `a` a dictionary makes `b` a dictionary too.
                        if (e->tokens.size() == 1 && e->tokens.front().kind == Token::Kind::dictionary &&
                            s.tokens.size() == 1 && s.tokens.front().kind == AstToken::Kind::macro) {
                            e->dict = std::make_unique<Dictionary>(*e->tokens.front().dict);
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
                             "'$" + s.key + "' is not a dictionary, so it cannot stand as an entry");
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
    std::unique_ptr<Dictionary> makeDict(const Source& src, const AstDict& ast, const Dictionary& parent,
                                         const std::string& name, const SourceLocation& where,
                                         bool included) {
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

    void include(const Source& src, const AstStatement& s, Dictionary& dict) {
        const bool etc = s.kind == AstStatement::Kind::includeEtc;
        const std::string name = s.tokens.empty() ? std::string() : s.tokens.front().text;
        const std::size_t at = s.begin;
        fs::path path;
        if (etc) {
            const auto dirs = options_.etcDirectories.empty() ? etcDirectories() : options_.etcDirectories;
            std::string searched;
            for (const auto& d : dirs) {
                std::error_code ec;
                if (fs::is_regular_file(d / name, ec)) {
                    path = d / name;
                    break;
                }
                searched += (searched.empty() ? "" : ", ") + d.string();
            }
            if (path.empty())
                fail(src, at,
                     "#includeEtc \"" + name + "\": not found in " +
                         (searched.empty() ? std::string("any etc directory (none configured)") : searched));
        } else {
            path = fs::path(name);
            if (path.is_relative()) path = src.directory / path;
            std::error_code ec;
            if (!fs::is_regular_file(path, ec))
                fail(src, at, "#include \"" + name + "\": cannot open file '" + path.string() + "'");
        }
        std::error_code ec;
        fs::path canonical = fs::weakly_canonical(path, ec);
        if (ec) canonical = path;
        if (std::find(chain.begin(), chain.end(), canonical) != chain.end()) {
            std::string loop;
            bool inLoop = false;
            for (const auto& f : chain) {
                if (f == canonical) inLoop = true;
                if (inLoop) loop += f.string() + " -> ";
            }
            fail(src, at, "include loop: " + loop + canonical.string());
        }
        std::string text;
        try {
            text = readFile(path);
        } catch (const InputError&) {
            fail(src, at, "cannot read included file '" + path.string() + "'");
        }
        chain.push_back(canonical);
        const Source inner(path.string(), std::move(text));
        buildFile(inner, dict, true);
        chain.pop_back();
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
                 "undefined macro '$" + name + "'" +
                     (guess.empty() ? std::string(" (only entries defined before it can be used)")
                                    : "; did you mean '$" + guess + "'?"));
        }
        e->read = true;  // a value used through a macro counts as used
        return e;
    }

    std::vector<Token> expand(const Source& src, const std::vector<AstToken>& in, Dictionary& dict,
                              const std::string& key) {
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
                        t.real = std::strtod(a.text.c_str(), nullptr);
                    } else {
                        t.real = double(t.integer);
                    }
                    break;
                }
                case AstToken::Kind::real:
                    t.kind = Token::Kind::real;
                    t.text = a.text;
                    t.real = std::strtod(a.text.c_str(), nullptr);
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
                    if (e->isDict()) {
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
                case AstToken::Kind::list:
                    t.kind = Token::Kind::list;
                    t.list = expand(src, a.list, dict, key);
                    break;
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

    const ReadOptions& options_;
};

fs::path canonicalOrSame(const fs::path& p) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(p, ec);
    return ec ? p : c;
}

}  // namespace

Dictionary Dictionary::parse(std::string_view text, const std::string& fileName, const ReadOptions& options) {
    const Source src(fileName, std::string(text));
    Dictionary dict;
    dict.setWhere(src.at(0));
    dict.closeBraceOffset = text.size();
    Builder builder(options);
    if (!fileName.empty()) builder.chain.push_back(canonicalOrSame(fileName));
    builder.buildFile(src, dict, false);
    return dict;
}

Dictionary Dictionary::read(const std::filesystem::path& file, const ReadOptions& options) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw InputError("cannot open dictionary file '" + file.string() + "'");
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
        throw InputError(where_, name_,
                         "cannot set '" + std::string(key) + "' to '" + std::string(valueText) + "'");
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
