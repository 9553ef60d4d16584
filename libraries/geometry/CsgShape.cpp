#include "geometry/CsgShape.hpp"

namespace mfdyn {

CsgShape::CsgShape(const Dictionary& dict, int dimension) : Shape(dict, dimension) {
    const Entry& e = dict.entry("shapes");
    if (e.isDict()) {
        const Dictionary& sub = *e.dict;
        for (const auto& s : sub.entries()) {
            if (!s->isDict()) throw sub.error(s->key, "expected a shape dictionary { type ...; }");
            shapes_.push_back(Shape::New(sub.subDict(s->key), dimension));
        }
    } else {
        const bool isList = e.tokens.size() == 1 && e.tokens[0].kind == Token::Kind::list;
        if (!isList)
            throw dict.error("shapes", "expected a list of shape dictionaries ( { type ...; } ... )");
        for (const Token& t : e.tokens[0].list) {
            if (t.kind != Token::Kind::dictionary || !t.dict)
                throw dict.error("shapes",
                                 "expected a shape dictionary { type ...; }, found '" + t.str() + "'");
            shapes_.push_back(Shape::New(*t.dict, dimension));
        }
    }
    if (shapes_.empty()) throw dict.error("shapes", "no shapes given");
}

CsgShape::~CsgShape() = default;

}  // namespace mfdyn
