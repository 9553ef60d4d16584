#include "particles/XmlElement.hpp"

#include "core/Error.hpp"

#include <cctype>
#include <cstdint>
#include <memory>
#include <unordered_set>

namespace mfdyn {

const std::string* XmlElement::findAttribute(std::string_view key) const {
    for (const auto& [k, v] : attributes)
        if (k == key) return &v;
    return nullptr;
}

const XmlElement* XmlElement::findChild(std::string_view childName) const {
    for (const auto& c : children)
        if (c.name == childName) return &c;
    return nullptr;
}

std::vector<const XmlElement*> XmlElement::childrenNamed(std::string_view childName) const {
    std::vector<const XmlElement*> found;
    for (const auto& c : children)
        if (c.name == childName) found.push_back(&c);
    return found;
}

std::string xmlEscape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

namespace {

class Parser {
public:
    Parser(std::string_view text, const std::string& fileName, std::string_view stopAt)
        : s_(text), file_(std::make_shared<const std::string>(fileName)), stopAt_(stopAt) {}

    XmlElement document(std::size_t* stopOffset) {
        skipProlog();
        if (!peek("<")) fail("expected the root element");
        XmlElement root;
        element(root, 1);
        if (stopped_) {
            if (stopOffset) *stopOffset = stopOffset_;
            return root;
        }
        skipMisc();
        if (pos_ != s_.size()) fail("content after the root element");
        if (!stopAt_.empty()) fail("no <" + std::string(stopAt_) + "> element");
        return root;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        SourceLocation where{file_, 1, 1};
        for (std::size_t i = 0; i < pos_ && i < s_.size(); ++i) {
            if (s_[i] == '\n') {
                ++where.line;
                where.column = 1;
            } else {
                ++where.column;
            }
        }
        throw InputError(where, "", "bad XML: " + what);
    }

    bool peek(std::string_view t) const { return s_.substr(pos_, t.size()) == t; }
    void expect(std::string_view t) {
        if (!peek(t)) fail("expected '" + std::string(t) + "'");
        pos_ += t.size();
    }
    static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
    void skipSpace() {
        while (pos_ < s_.size() && space(s_[pos_])) ++pos_;
    }
    void skipUntil(std::string_view end) {
        std::size_t at = s_.find(end, pos_);
        if (at == std::string_view::npos) fail("unterminated construct, missing '" + std::string(end) + "'");
        pos_ = at + end.size();
    }
    void skipMisc() {
        for (;;) {
            skipSpace();
            if (peek("<!--"))
                skipUntil("-->");
            else if (peek("<?"))
                skipUntil("?>");
            else
                return;
        }
    }
    void skipProlog() {
        if (peek("\xEF\xBB\xBF")) pos_ += 3;
        skipMisc();
        if (peek("<!DOCTYPE")) fail("DOCTYPE is not supported");
    }
    static bool nameChar(char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == ':' ||
               static_cast<unsigned char>(c) >= 0x80;
    }
    std::string name() {
        std::size_t start = pos_;
        while (pos_ < s_.size() && nameChar(s_[pos_])) ++pos_;
        if (pos_ == start) fail("expected a name");
        return std::string(s_.substr(start, pos_ - start));
    }

    // Character data up to `end` with entities resolved.
    std::string characters(char end) {
        std::string out;
        while (pos_ < s_.size() && s_[pos_] != end) {
            char c = s_[pos_];
            if (c == '<') fail("'<' inside a value");
            if (c != '&') {
                out += c;
                ++pos_;
                continue;
            }
            std::size_t semi = s_.find(';', pos_);
            if (semi == std::string_view::npos || semi - pos_ > 12) fail("bad entity reference");
            std::string_view ref = s_.substr(pos_ + 1, semi - pos_ - 1);
            if (ref == "amp")
                out += '&';
            else if (ref == "lt")
                out += '<';
            else if (ref == "gt")
                out += '>';
            else if (ref == "quot")
                out += '"';
            else if (ref == "apos")
                out += '\'';
            else if (ref.size() > 1 && ref[0] == '#')
                appendCodePoint(out, ref);
            else
                fail("unknown entity '&" + std::string(ref) + ";'");
            pos_ = semi + 1;
        }
        return out;
    }
    void appendCodePoint(std::string& out, std::string_view ref) {
        std::uint32_t cp = 0;
        bool hex = ref[1] == 'x';
        for (char c : ref.substr(hex ? 2 : 1)) {
            int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
                    : hex && std::isxdigit(static_cast<unsigned char>(c))
                        ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                        : -1;
            if (d < 0) fail("bad character reference");
            cp = cp * (hex ? 16 : 10) + std::uint32_t(d);
            if (cp > 0x10FFFF) fail("bad character reference");
        }
        if (cp < 0x80) {
            out += char(cp);
        } else if (cp < 0x800) {
            out += char(0xC0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += char(0xE0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        } else {
            out += char(0xF0 | (cp >> 18));
            out += char(0x80 | ((cp >> 12) & 0x3F));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
    }

    // The line of pos_, counted on from where the last call left off: pos_ only moves forward,
    // so the whole parse counts each character once.
    int lineHere() {
        for (; lineCounted_ < pos_; ++lineCounted_) line_ += s_[lineCounted_] == '\n';
        return line_;
    }

    // At '<' of a start tag. Returns with pos_ after the end tag (or after the stop tag).
    // `depth` is 1 for the root element.
    void element(XmlElement& e, int depth) {
        if (depth > XmlElement::maxDepth)
            fail("elements nested more than " + std::to_string(XmlElement::maxDepth) + " deep");
        e.line = lineHere();
        expect("<");
        e.name = name();
        for (;;) {
            bool hadSpace = pos_ < s_.size() && space(s_[pos_]);
            skipSpace();
            if (pos_ >= s_.size()) fail("unterminated start tag <" + e.name + ">");
            if (peek("/>")) {
                pos_ += 2;
                if (e.name == stopAt_) stop();
                return;
            }
            if (peek(">")) {
                ++pos_;
                break;
            }
            if (!hadSpace) fail("expected white space between attributes");
            std::string key = name();
            skipSpace();
            expect("=");
            skipSpace();
            if (pos_ >= s_.size() || (s_[pos_] != '"' && s_[pos_] != '\'')) fail("expected a quoted value");
            char quote = s_[pos_++];
            std::string value = characters(quote);
            if (pos_ >= s_.size()) fail("unterminated attribute value");
            ++pos_;
            if (repeated(e, key)) fail("attribute '" + key + "' repeated");
            e.attributes.emplace_back(std::move(key), std::move(value));
        }
        if (e.name == stopAt_) return stop();
        content(e, depth);
    }

    // Whether `key` is already among e's attributes: a linear search for the few attributes
    // real elements have, a hash set beyond that, so that an element with a million attributes
    // is not a quadratic wait.
    bool repeated(const XmlElement& e, const std::string& key) {
        constexpr std::size_t few = 16;
        if (e.attributes.size() < few) return e.findAttribute(key) != nullptr;
        if (e.attributes.size() == few) {
            keys_.clear();
            for (const auto& [k, v] : e.attributes) keys_.insert(k);
        }
        return !keys_.insert(key).second;
    }

    void stop() {
        stopped_ = true;
        stopOffset_ = pos_;
    }

    void content(XmlElement& e, int depth) {
        for (;;) {
            if (pos_ >= s_.size()) fail("element <" + e.name + "> is not closed");
            if (peek("</")) {
                pos_ += 2;
                std::string closing = name();
                if (closing != e.name) fail("</" + closing + "> closes <" + e.name + ">");
                skipSpace();
                expect(">");
                return;
            }
            if (peek("<!--")) {
                skipUntil("-->");
            } else if (peek("<![CDATA[")) {
                fail("CDATA is not supported");
            } else if (peek("<?")) {
                skipUntil("?>");
            } else if (peek("<")) {
                e.children.emplace_back();
                element(e.children.back(), depth + 1);
                if (stopped_) return;
            } else {
                e.text += characters('<');
            }
        }
    }

    std::string_view s_;
    std::size_t pos_ = 0;
    std::shared_ptr<const std::string> file_;
    std::string_view stopAt_;
    bool stopped_ = false;
    std::size_t stopOffset_ = 0;
    int line_ = 1;                          // the line of s_[lineCounted_]
    std::size_t lineCounted_ = 0;           // characters up to here are counted in line_
    std::unordered_set<std::string> keys_;  // of the element being read, once it has many
};

}  // namespace

XmlElement XmlElement::parse(std::string_view text, const std::string& fileName, std::string_view stopAt,
                             std::size_t* stopOffset) {
    return Parser(text, fileName, stopAt).document(stopOffset);
}

}  // namespace mfdyn
