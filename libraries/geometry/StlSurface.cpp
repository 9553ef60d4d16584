// stlSurface: the solid bounded by a closed, manifold triangle surface from an ASCII or binary STL
// file. Inside test: CGAL::Side_of_triangle_mesh (CGAL 5.5 Polygon Mesh Processing), which casts
// rays through an AABB tree of the triangles (CGAL::AABB_tree over face-graph triangle
// primitives) and counts crossings, retrying with another ray when one grazes an edge or vertex,
// so points are classified exactly by the kernel's filtered predicates. Points on the surface
// count as outside, like the other shapes' boundaries.
//
// Volume: the polyhedron's exact volume by the divergence theorem, V = Σ_t (a·(b×c))/6 over the
// triangles (a, b, c) (signed tetrahedra with the origin), for outward-oriented triangles.
//
// STL (3D Systems' StereoLithography format): binary is an 80-byte header, a uint32 triangle
// count and 50 bytes per triangle (normal, three vertices as float32, a uint16 attribute);
// ASCII is `solid ... facet normal ... outer loop vertex x y z ×3 endloop endfacet ... endsolid`.
// A file is binary when its size is exactly 84 + 50 n for the count n in its header (ASCII files
// also start with "solid", so the first word cannot decide). Normals in the file are ignored:
// orientation comes from the vertex order.
//
// STL repeats each vertex in every triangle that uses it; vertices are merged when their
// coordinates are bit-identical, which is how exporters write shared corners. The surface must
// then be closed and manifold: every edge shared by exactly two triangles (an open or
// non-manifold surface has no well-defined inside, and ray counting would silently misclassify).
#include "geometry/StlSurface.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace mfdyn {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Triangle = std::array<std::array<double, 3>, 3>;

std::vector<Triangle> readBinary(const std::string& bytes, std::uint32_t count) {
    std::vector<Triangle> out(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + 84 + 50 * std::size_t(t) + 12;  // skip the normal
        for (int v = 0; v < 3; ++v)
            for (int c = 0; c < 3; ++c) {
                float value;
                std::memcpy(&value, record + 4 * (3 * v + c), 4);
                out[t][v][c] = value;
            }
    }
    return out;
}

std::vector<Triangle> readAscii(const std::string& text, const std::string& file) {
    std::istringstream in(text);
    std::vector<Triangle> out;
    std::string word;
    Triangle tri{};
    int vertex = 0;
    while (in >> word) {
        if (word == "vertex") {
            if (vertex == 3) throw InputError(file + ": a facet with more than three vertices");
            for (int c = 0; c < 3; ++c)
                if (!(in >> tri[vertex][c])) throw InputError(file + ": unreadable vertex coordinates");
            ++vertex;
        } else if (word == "endfacet") {
            if (vertex != 3)
                throw InputError(file + ": a facet with " + std::to_string(vertex) + " vertices");
            out.push_back(tri);
            vertex = 0;
        }
    }
    return out;
}

std::vector<Triangle> readStl(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot open STL file " + path.string());
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() >= 84) {
        std::uint32_t count;
        std::memcpy(&count, bytes.data() + 80, 4);
        if (bytes.size() == 84 + 50 * std::size_t(count)) return readBinary(bytes, count);
    }
    if (bytes.compare(0, 5, "solid") != 0)
        throw InputError(path.string() +
                         ": neither an ASCII STL (starting 'solid') nor a binary STL of consistent size");
    return readAscii(bytes, path.string());
}

}  // namespace

struct StlSurface::Impl {
    Mesh mesh;
    std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
};

StlSurface::StlSurface(const Dictionary& dict, int dimension)
    : Shape(dict, dimension), impl_(std::make_unique<Impl>()) {
    if (dimension != 3) throw dict.error("type", "stlSurface needs a 3D case");
    std::filesystem::path path = dict.get<std::string>("file");
    if (path.is_relative() && dict.topLevel().where().file) {
        const std::filesystem::path dictFile = *dict.topLevel().where().file;
        if (dictFile.has_parent_path()) path = dictFile.parent_path().parent_path() / path;
    }
    const std::string name = path.string();
    // The file's own errors are reported at the `file` entry that named it.
    std::vector<Triangle> triangles;
    try {
        triangles = readStl(path);
    } catch (const InputError& e) {
        throw dict.error("file", e.what());
    }
    if (triangles.empty()) throw dict.error("file", name + " holds no triangles");

    // Merge bit-identical vertices and count how many triangles use each undirected edge.
    std::map<std::array<double, 3>, Mesh::Vertex_index> vertices;
    std::map<std::pair<std::size_t, std::size_t>, int> edges;
    std::vector<std::array<Mesh::Vertex_index, 3>> faces;
    faces.reserve(triangles.size());
    for (const auto& t : triangles) {
        // A binary file's float32 can hold inf or NaN, which no inside test can classify.
        for (const auto& corner : t)
            for (double c : corner)
                if (!std::isfinite(c))
                    throw dict.error("file", name + ": triangle " + std::to_string(faces.size() + 1) +
                                                 " has a non-finite vertex coordinate");
        std::array<Mesh::Vertex_index, 3> f;
        for (int v = 0; v < 3; ++v) {
            auto [it, added] = vertices.try_emplace(t[v]);
            if (added) it->second = impl_->mesh.add_vertex(Point(t[v][0], t[v][1], t[v][2]));
            f[v] = it->second;
        }
        if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
            throw dict.error("file", name + " has a degenerate triangle (two equal corners)");
        for (int v = 0; v < 3; ++v) {
            const std::size_t a = f[v], b = f[(v + 1) % 3];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
        faces.push_back(f);
    }
    std::size_t open = 0, nonManifold = 0;
    for (const auto& [edge, count] : edges) {
        if (count == 1)
            ++open;
        else if (count > 2)
            ++nonManifold;
    }
    if (open > 0 || nonManifold > 0)
        throw dict.error("file", name + " is not a closed manifold surface: " + std::to_string(open) +
                                     " edges belong to one triangle only (holes) and " +
                                     std::to_string(nonManifold) +
                                     " to more than two; every edge must be shared by exactly two triangles");
    for (const auto& f : faces)
        if (impl_->mesh.add_face(f[0], f[1], f[2]) == Mesh::null_face())
            throw dict.error("file",
                             name +
                                 " has inconsistently oriented triangles (a shared edge runs the same way "
                                 "in both): it does not bound a solid");

    double v6 = 0;
    box_.min = box_.max = triangles.front()[0];
    for (const auto& t : triangles) {
        const auto& [a, b, c] = t;
        v6 += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0]);
        for (const auto& p : t)
            for (int d = 0; d < 3; ++d) {
                box_.min[d] = std::min(box_.min[d], p[d]);
                box_.max[d] = std::max(box_.max[d], p[d]);
            }
    }
    // Inward-facing triangles give a negative sum; the enclosed volume is the same either way.
    volume_ = std::abs(v6) / 6;
    impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(impl_->mesh);
}

StlSurface::~StlSurface() = default;

bool StlSurface::inside(const double* x) const {
    return (*impl_->side)(Point(x[0], x[1], x[2])) == CGAL::ON_BOUNDED_SIDE;
}

std::size_t StlSurface::triangles() const {
    return impl_->mesh.number_of_faces();
}

MFDYN_REGISTER(Shape, StlSurface, "stlSurface",
               "solid inside a closed triangulated surface from an STL file");

}  // namespace mfdyn
