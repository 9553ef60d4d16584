#include "particles/XmlElement.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

using namespace mfdyn;

TEST(XmlElement, ParsesElementsAttributesTextAndEntities) {
    const XmlElement root = XmlElement::parse(
        "<?xml version=\"1.0\"?>\n<!-- c -->\n<a x=\"1 &amp; 2\" y='&lt;&#65;&#x42;'>\n  <b/>text<c "
        "k=\"v\">in</c>\n</a>\n",
        "t.xml");
    EXPECT_EQ(root.name, "a");
    EXPECT_EQ(*root.findAttribute("x"), "1 & 2");
    EXPECT_EQ(*root.findAttribute("y"), "<AB");
    ASSERT_EQ(root.children.size(), 2u);
    EXPECT_EQ(root.findChild("c")->text, "in");
    EXPECT_EQ(root.findChild("c")->line, 4);  // declaration, comment, <a>, then <b/><c>
    EXPECT_EQ(xmlEscape("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&apos;");
}

TEST(XmlElement, StopsAtANamedStartTag) {
    const std::string text = "<V><P n=\"1\"/><A enc=\"raw\">_\x01\x02 binary < & garbage";
    std::size_t stop = 0;
    const XmlElement root = XmlElement::parse(text, "t.vtp", "A", &stop);
    ASSERT_NE(root.findChild("A"), nullptr);
    EXPECT_EQ(*root.findChild("A")->findAttribute("enc"), "raw");
    EXPECT_EQ(text[stop], '_');
}

TEST(XmlElement, MalformedInputNamesFileLineAndColumn) {
    for (const char* bad : {"<a><b></a>", "<a x=1/>", "<a>", "<a x=\"1\" x=\"2\"/>", "<a>&bogus;</a>",
                            "<a/><b/>", "", "<a>\n  <b c=\"d\"\n</a>"}) {
        try {
            XmlElement::parse(bad, "bad.xml");
            ADD_FAILURE() << "accepted: " << bad;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("bad.xml:", 0), 0u) << e.what();
        }
    }
}

TEST(XmlElement, DeepNestingIsAnErrorNotAStackOverflow) {
    // 100 000 nested elements: on a668953 the recursive parser overflowed the stack (SIGSEGV at
    // about 60 000 levels) in every solver and particleInfo.
    const int levels = 100000;
    std::string text;
    text.reserve(std::size_t(levels) * 8);
    for (int i = 0; i < levels; ++i) text += "<a>\n";  // element k on line k
    for (int i = 0; i < levels; ++i) text += "</a>";
    try {
        XmlElement::parse(text, "deep.pvd");
        ADD_FAILURE() << "no error for " << levels << " nested elements";
    } catch (const InputError& e) {
        const std::string what = e.what();
        // The first element too deep is the one refused, on its own line.
        EXPECT_EQ(what.rfind("deep.pvd:" + std::to_string(XmlElement::maxDepth + 1) + ":1:", 0), 0u) << what;
        EXPECT_NE(what.find("nested more than " + std::to_string(XmlElement::maxDepth) + " deep"),
                  std::string::npos)
            << what;
    }
    // Exactly maxDepth levels are still a document.
    std::string ok;
    for (int i = 0; i < XmlElement::maxDepth; ++i) ok += "<a>";
    for (int i = 0; i < XmlElement::maxDepth; ++i) ok += "</a>";
    EXPECT_NO_THROW(XmlElement::parse(ok, "ok.xml"));
}

TEST(XmlElement, LineNumbersStayRightAcrossAWholeDocument) {
    // Lines are now counted on from element to element; each must still be its own.
    std::string text = "<?xml version=\"1.0\"?>\n<r>\n";
    for (int i = 0; i < 1000; ++i) text += (i % 2 ? "  <e/>\n" : "  <!-- c\n -->\n  <e a=\"x\n y\"/>\n");
    text += "</r>\n";
    const XmlElement root = XmlElement::parse(text, "lines.xml");
    ASSERT_EQ(root.children.size(), 1000u);
    EXPECT_EQ(root.line, 2);
    int line = 3;
    for (int i = 0; i < 1000; ++i) {
        if (i % 2 == 0) line += 2;  // the comment's two lines
        EXPECT_EQ(root.children[std::size_t(i)].line, line) << i;
        line += i % 2 ? 1 : 2;  // the attribute value holds a newline
    }
    // And a failure after all of them still names its own line.
    try {
        XmlElement::parse(text + "<x/>", "lines.xml");
        ADD_FAILURE() << "content after the root accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("lines.xml:" + std::to_string(line + 1) + ":", 0), 0u)
            << e.what();
    }
}

TEST(XmlElement, ManyAttributesAreCheckedForRepeatsQuickly) {
    // 100 000 distinct attributes, then one repeated: found, and without a quadratic search
    // (which was 5e9 comparisons here).
    std::string text = "<a";
    for (int i = 0; i < 100000; ++i) text += " k" + std::to_string(i) + "=\"\"";
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(XmlElement::parse(text + "/>", "wide.xml").attributes.size(), 100000u);
    try {
        XmlElement::parse(text + " k77=\"\"/>", "wide.xml");
        ADD_FAILURE() << "repeated attribute accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("attribute 'k77' repeated"), std::string::npos) << e.what();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 2.0) << "linear: each is a hash look-up";
}
