#pragma once
// Just enough XML for the files mfdyn writes itself (VTK headers, .pvd indices): elements,
// attributes, character data, comments, the declaration, the five predefined entities and
// numeric character references. No DTDs, namespaces or CDATA. Parsing can stop at the start
// tag of a named element, which is how the VTK reader reads the header in front of raw
// appended binary data (which no XML parser can read).
//
// Corrupt or hostile input ends in an InputError, never in a crash or a long wait: elements
// nest at most maxDepth deep (the parser recurses; 60 000 levels overflowed the stack), the
// line of each element is counted on from the previous one (counting from the start for each
// element made a 50 000-entry .pvd take 7.5 s), and repeated attributes are found through a
// hash set once an element has many.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mfdyn {

class XmlElement {
public:
    // VTK files nest about 6 deep; this leaves room for any sane document and keeps the
    // recursion (two frames per level) far from the stack's end.
    static constexpr int maxDepth = 256;

    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;
    std::vector<XmlElement> children;
    std::string text;  // character data directly inside, entities resolved
    int line = 0;      // of the start tag, for messages

    const std::string* findAttribute(std::string_view key) const;
    const XmlElement* findChild(std::string_view childName) const;
    std::vector<const XmlElement*> childrenNamed(std::string_view childName) const;

    // Parse a document. `fileName` goes into messages ("file:line:column: bad XML: ...").
    // When `stopAt` is given, parsing ends at the first start tag of that name (which, with
    // its attributes, becomes the last child of its parent), *stopOffset is set to the offset
    // just after its '>', and elements still open are accepted as they are.
    static XmlElement parse(std::string_view text, const std::string& fileName, std::string_view stopAt = {},
                            std::size_t* stopOffset = nullptr);
};

// Text with &, <, >, " and ' escaped, for attribute values and character data.
std::string xmlEscape(std::string_view text);

}  // namespace mfdyn
