#include "particles/TimeDirectoryReader.hpp"

#include "core/Error.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/RegularFile.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/XmlElement.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <new>
#include <numeric>
#include <set>

namespace mfdyn {

namespace fs = std::filesystem;

namespace {

// There, or at least not known to be missing (a link to itself is there, and the reader says
// what is wrong with it): a file that cannot be looked at must not be passed over silently.
bool present(const fs::path& file) {
    std::error_code ec;
    return fs::symlink_status(file, ec).type() != fs::file_type::not_found;
}

struct Piece {
    std::string source;  // as the index names it
    int line = 0;        // of its <Piece> in the index
    ParticleFile data;
};

class IndexReader {
public:
    explicit IndexReader(const fs::path& file) : file_(file) {}

    ParticleFile read() {
        const RegularFile text(file_);  // a FIFO is an error, not a wait
        const XmlElement root = XmlElement::parse(text.view(), file_.string());
        const std::string* type = root.findAttribute("type");
        if (root.name != "VTKFile" || !type || *type != "PPolyData")
            fail("not a VTK parallel PolyData index (<VTKFile type=\"PPolyData\">)");
        const XmlElement* polyData = root.findChild("PPolyData");
        if (!polyData) fail("<VTKFile> has no <PPolyData>");
        std::set<std::string> indexFields;
        const XmlElement* pointData = polyData->findChild("PPointData");
        if (pointData)
            for (const XmlElement* e : pointData->childrenNamed("PDataArray"))
                if (const std::string* name = e->findAttribute("Name")) indexFields.insert(*name);

        std::vector<Piece> pieces;
        std::map<std::string, int> lineOf;
        for (const XmlElement* e : polyData->childrenNamed("Piece")) {
            const std::string* source = e->findAttribute("Source");
            const std::string where = "<Piece> at line " + std::to_string(e->line);
            if (!source || source->empty()) fail(where + " has no Source");
            const fs::path relative(*source);
            // Pieces lie beside their index: an absolute name or one that climbs out is not a
            // piece of this time (and a damaged index must not make the reader open any file).
            bool climbs = false;
            for (const auto& part : relative) climbs = climbs || part == "..";
            if (relative.is_absolute() || climbs)
                fail(where + ": Source \"" + *source + "\" is not a file beside the index");
            if (auto [it, fresh] = lineOf.emplace(*source, e->line); !fresh)
                fail("piece '" + *source + "' is listed twice (lines " + std::to_string(it->second) +
                     " and " + std::to_string(e->line) + ")");
            pieces.push_back(Piece{*source, e->line, {}});
        }
        if (pieces.empty()) fail("it lists no <Piece>");

        for (Piece& piece : pieces) {
            try {
                piece.data = readVtp(file_.parent_path() / piece.source);
            } catch (const Error& e) {
                fail("piece '" + piece.source + "' (line " + std::to_string(piece.line) +
                     ") cannot be read: " + e.what());
            }
            if (pointData) checkAgainstIndex(piece, indexFields);
        }
        for (std::size_t k = 1; k < pieces.size(); ++k) checkAgrees(pieces[0], pieces[k]);
        return merge(pieces);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("particle index '" + file_.string() + "': " + what);
    }

    static std::map<std::string, FieldKind> pointFields(const ParticleSetBase& set) {
        std::map<std::string, FieldKind> fields;
        for (const auto& f : set.fields())
            if (f->name() != "position") fields.emplace(f->name(), f->kind());
        return fields;
    }

    static std::string nameList(const std::vector<std::string>& names) {
        std::string text;
        for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
        return text.empty() ? "none" : text;
    }

    // The index and the piece list the same PointData arrays (an index left from another write
    // would name fields the pieces do not have).
    void checkAgainstIndex(const Piece& piece, const std::set<std::string>& indexFields) const {
        std::vector<std::string> missing, extra;
        const auto fields = pointFields(*piece.data.particles);
        for (const auto& name : indexFields)
            if (!fields.count(name)) missing.push_back(name);
        for (const auto& [name, kind] : fields)
            if (!indexFields.count(name)) extra.push_back(name);
        if (!missing.empty() || !extra.empty())
            fail("piece '" + piece.source + "' does not hold the arrays the index lists: missing " +
                 nameList(missing) + "; not listed " + nameList(extra));
    }

    // A shorter list of names must begin the longer one (ids index them).
    void checkNames(const Piece& first, const Piece& other, const std::vector<std::string>& a,
                    const std::vector<std::string>& b, const char* what) const {
        const std::size_t n = std::min(a.size(), b.size());
        for (std::size_t k = 0; k < n; ++k)
            if (a[k] != b[k])
                fail(std::string(what) + " disagree: id " + std::to_string(k) + " is '" + a[k] +
                     "' in piece '" + first.source + "' but '" + b[k] + "' in piece '" + other.source + "'");
    }

    void checkAgrees(const Piece& first, const Piece& other) const {
        const ParticleSetBase& a = *first.data.particles;
        const ParticleSetBase& b = *other.data.particles;
        const std::string pair = "pieces '" + first.source + "' and '" + other.source + "'";
        if (a.dimension() != b.dimension())
            fail(pair + " disagree in dimension (" + std::to_string(a.dimension()) + "D and " +
                 std::to_string(b.dimension()) + "D)");
        const auto fa = pointFields(a), fb = pointFields(b);
        std::vector<std::string> onlyA, onlyB;
        for (const auto& [name, kind] : fa) {
            const auto it = fb.find(name);
            if (it == fb.end())
                onlyA.push_back(name);
            else if (it->second != kind)
                fail(pair + " disagree in field '" + name + "': " + kindName(kind) + " and " +
                     kindName(it->second));
        }
        for (const auto& [name, kind] : fb)
            if (!fa.count(name)) onlyB.push_back(name);
        if (!onlyA.empty() || !onlyB.empty())
            fail(pair + " disagree in fields: only in '" + first.source + "': " + nameList(onlyA) +
                 "; only in '" + other.source + "': " + nameList(onlyB));
        if (first.data.hasTime != other.data.hasTime ||
            (first.data.hasTime && first.data.time != other.data.time))
            fail(pair + " are of different times");
        checkNames(first, other, a.regionNames, b.regionNames, "region names");
        checkNames(first, other, a.materialNames, b.materialNames, "material names");
    }

    ParticleFile merge(std::vector<Piece>& pieces) const {
        const ParticleSetBase& first = *pieces[0].data.particles;
        std::size_t total = 0;
        std::int64_t nextGlobalId = 0;
        std::vector<std::string> regionNames, materialNames;
        for (const Piece& piece : pieces) {
            const ParticleSetBase& p = *piece.data.particles;
            total += p.size();
            nextGlobalId = std::max(nextGlobalId, p.nextGlobalId());
            if (p.regionNames.size() > regionNames.size()) regionNames = p.regionNames;
            if (p.materialNames.size() > materialNames.size()) materialNames = p.materialNames;
        }
        ParticleFile result;
        result.time = pieces[0].data.time;
        result.hasTime = pieces[0].data.hasTime;
        result.particles = withDimension(first.dimension(), [&](auto d) -> std::unique_ptr<ParticleSetBase> {
            constexpr int Dim = decltype(d)::value;
            return std::make_unique<ParticleSet<Dim>>(total);
        });
        ParticleSetBase& set = *result.particles;
        std::vector<std::size_t> pieceOf(total);  // for the message about a repeated id
        for (const auto& f : first.fields()) {
            FieldBase* merged = set.findField(f->name());
            if (!merged) merged = &set.addField(f->name(), f->kind());
            char* out = static_cast<char*>(merged->data());
            std::size_t offset = 0;
            for (const Piece& piece : pieces) {
                const FieldBase& part = piece.data.particles->field(f->name());
                const std::size_t bytes = part.size() * part.elementBytes();
                if (bytes) std::memcpy(out + offset * merged->elementBytes(), part.data(), bytes);
                offset += part.size();
            }
        }
        for (std::size_t k = 0, offset = 0; k < pieces.size(); ++k) {
            const std::size_t n = pieces[k].data.particles->size();
            std::fill(pieceOf.begin() + std::ptrdiff_t(offset), pieceOf.begin() + std::ptrdiff_t(offset + n),
                      k);
            offset += n;
            pieces[k].data.particles.reset();  // copied: the memory goes back before the sort
        }

        // In globalId order: the order a one-process run writes and restart tests compare.
        const std::vector<std::int64_t>& id = set.requireField<std::int64_t>("globalId");
        std::vector<std::size_t> order(total);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
        for (std::size_t k = 1; k < total; ++k)
            if (id[order[k]] == id[order[k - 1]])
                fail("globalId " + std::to_string(id[order[k]]) + " is held by piece '" +
                     pieces[pieceOf[order[k - 1]]].source + "' and by piece '" +
                     pieces[pieceOf[order[k]]].source + "'");
        set.reorder(order);
        set.regionNames = std::move(regionNames);
        set.materialNames = std::move(materialNames);
        set.reserveGlobalIdsBelow(nextGlobalId);
        set.setSource(file_.string());
        return result;
    }

    fs::path file_;
};

}  // namespace

fs::path timeParticleFile(const fs::path& timeDir) {
    const fs::path single = timeDir / particleFileName, index = timeDir / particleIndexFileName;
    if (!present(single) && present(index)) return index;
    return single;
}

ParticleFile readTimeParticles(const fs::path& timeDir) {
    const fs::path file = timeParticleFile(timeDir);
    if (!present(file))
        throw InputError("no particles in '" + timeDir.string() + "': neither " + particleFileName + " nor " +
                         particleIndexFileName + " is there");
    if (file.filename() == particleIndexFileName) return readPvtp(file);
    return readVtp(file);
}

ParticleFile readPvtp(const fs::path& file) {
    try {
        return IndexReader(file).read();
    } catch (const std::bad_alloc&) {
        throw InputError("particle index '" + file.string() +
                         "': its particles need more memory than there is");
    }
}

}  // namespace mfdyn
