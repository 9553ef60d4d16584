#include "particles/XmlElement.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

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
