#include "functionObjects/GatheredParticles.hpp"

#include "core/Communicator.hpp"
#include "particles/ParticleSet.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

namespace mfdyn {

namespace {

// The fields' names, kinds and components, one line each: what every rank must pack alike for
// the bytes to mean the same on the receiving side.
std::string layoutOf(const std::vector<const FieldBase*>& fields) {
    std::string layout;
    for (const FieldBase* f : fields)
        layout += f->name() + " " + kindName(f->kind()) + " " + std::to_string(f->components()) + "\n";
    return layout;
}

template <class T>
void put(std::vector<char>& buffer, const T& value) {
    const char* bytes = reinterpret_cast<const char*>(&value);
    buffer.insert(buffer.end(), bytes, bytes + sizeof(T));
}

template <class T>
T take(const std::vector<char>& buffer, std::size_t& at) {
    T value;
    std::memcpy(&value, buffer.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

}  // namespace

GatheredParticles::GatheredParticles(const RunContext& run) : run_(run) {}

GatheredParticles::~GatheredParticles() = default;

const ParticleSetBase& GatheredParticles::particles() {
    if (!copy_) refresh();
    return *copy_;
}

bool GatheredParticles::gathers(const std::string& field) const {
    return !selected_ || selected_->count(field) || field == "globalId" || field == "region";
}

void GatheredParticles::select(const std::optional<std::set<std::string>>& fields) {
    selected_ = fields;
    if (!copy_) return;
    std::vector<std::string> dropped;
    for (const auto& name : copy_->fieldNames())
        if (!gathers(name)) dropped.push_back(name);
    for (const auto& name : dropped) copy_->removeField(name);
}

void GatheredParticles::refresh() {
    const FieldStore& run = run_.fields();
    const std::size_t owned = run_.ownedParticles();
    // By name, so that the ranks agree on the order whatever order their fields were made in.
    std::vector<const FieldBase*> fields;
    for (const auto& f : run.fields())
        if (gathers(f->name())) fields.push_back(f.get());
    std::sort(fields.begin(), fields.end(),
              [](const FieldBase* a, const FieldBase* b) { return a->name() < b->name(); });
    const std::string layout = layoutOf(fields);

    // [layout length, layout, particle count, each field's owned values in turn]
    std::vector<char> mine;
    std::size_t bytes = 0;
    for (const FieldBase* f : fields) bytes += owned * f->elementBytes();
    mine.reserve(2 * sizeof(std::uint64_t) + layout.size() + bytes);
    put(mine, std::uint64_t(layout.size()));
    mine.insert(mine.end(), layout.begin(), layout.end());
    put(mine, std::uint64_t(owned));
    for (const FieldBase* f : fields) {
        const char* data = static_cast<const char*>(f->data());
        mine.insert(mine.end(), data, data + owned * f->elementBytes());
    }
    const std::vector<std::vector<char>> all = Communicator::allGatherVariable(mine);
    mine = {};

    std::vector<std::size_t> counts(all.size()), dataAt(all.size());
    std::size_t total = 0;
    for (std::size_t r = 0; r < all.size(); ++r) {
        std::size_t at = 0;
        const auto length = std::size_t(take<std::uint64_t>(all[r], at));
        const std::string theirs(all[r].data() + at, length);
        at += length;
        if (theirs != layout)
            throw Error("function objects: rank " + std::to_string(r) + " holds the particle fields\n" +
                        theirs + "and " + Communicator::rankName() + " these:\n" + layout +
                        "(every rank must hold the same fields for its particles to be gathered)");
        counts[r] = std::size_t(take<std::uint64_t>(all[r], at));
        dataAt[r] = at;
        total += counts[r];
    }

    if (!copy_) {
        copy_ = withDimension(run.dimension(), [](auto dim) -> std::unique_ptr<ParticleSetBase> {
            return std::make_unique<ParticleSet<decltype(dim)::value>>(0);
        });
        // ParticleSet makes position, globalId and region: those not gathered would read as zeros.
        for (const char* made : {"position", "globalId", "region"})
            if (!run.findField(made) || !gathers(made)) copy_->removeField(made);
    }
    if (const auto* set = dynamic_cast<const ParticleSetBase*>(&run)) {
        copy_->regionNames = set->regionNames;
        copy_->materialNames = set->materialNames;
    }
    for (const FieldBase* f : fields)
        if (!copy_->findField(f->name())) copy_->addField(f->name(), f->kind());
    copy_->resize(total);

    // Rank by rank, each field's block to its place: rank r's particles at [first_r, first_r + n_r).
    std::size_t first = 0;
    for (std::size_t r = 0; r < all.size(); ++r) {
        std::size_t at = dataAt[r];
        for (const FieldBase* f : fields) {
            FieldBase& into = copy_->field(f->name());
            const std::size_t blockBytes = counts[r] * f->elementBytes();
            std::memcpy(static_cast<char*>(into.data()) + first * f->elementBytes(), all[r].data() + at,
                        blockBytes);
            at += blockBytes;
        }
        first += counts[r];
    }

    // Each rank's owned particles are in id order after a migration; the pieces of the ranks
    // interleave, and particles appended since are at the end.
    const auto& id = copy_->requireField<std::int64_t>("globalId");
    if (!std::is_sorted(id.begin(), id.end())) {
        std::vector<std::size_t> order(total);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
        copy_->reorder(order);
    }
    ++refreshes_;
}

const FieldStore& FunctionObjectContext::fields() const {
    if (scope_ == ParticleScope::owned) return run_.fields();
    return gathered_.particles();
}

std::size_t FunctionObjectContext::ownedParticles() const {
    if (scope_ == ParticleScope::owned) return run_.ownedParticles();
    return gathered_.particles().size();
}

}  // namespace mfdyn
