// Domain decomposition (Decomposition.hpp): migration and halos over Communicator, the cuts
// from Partitioner (Zoltan). The byte layouts are the fields' own (FieldBase::data(), every
// element elementBytes() of doubles or int64), so any field a model creates travels without
// code of its own.
#include "particles/Decomposition.hpp"

#include "core/Communicator.hpp"
#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <numeric>
#include <sstream>

namespace mfdyn {

namespace {

// Every rank must hold the same fields in the same order for the bytes of a particle to mean
// the same thing on arrival: a digest of the names and sizes, compared across ranks.
std::uint64_t fieldDigest(const ParticleSetBase& particles) {
    std::uint64_t h = 1469598103934665603ull;
    for (const auto& f : particles.fields()) {
        for (char c : f->name()) h = (h ^ std::uint64_t(std::uint8_t(c))) * 1099511628211ull;
        h = (h ^ f->elementBytes()) * 1099511628211ull;
    }
    return h;
}

void checkSameFields(const ParticleSetBase& particles) {
    const std::uint64_t mine = fieldDigest(particles);
    std::vector<std::uint64_t> all(std::size_t(Communicator::size()));
    Communicator::allGather(&mine, sizeof mine, all.data());
    for (std::uint64_t other : all)
        if (other != mine)
            throw Error("decomposition: the ranks hold different particle fields (" + Communicator::rankName() +
                        " has " + std::to_string(particles.fields().size()) +
                        "); a model created a field on some ranks only");
}

}  // namespace

Decomposition::Decomposition(const Settings& settings, int dimension)
    : settings_(settings),
      dimension_(dimension),
      partitioner_(std::make_unique<Partitioner>(settings.method, dimension, 1.05)) {}

Decomposition::~Decomposition() = default;

std::vector<double> Decomposition::coordinates(const ParticleSetBase& particles,
                                               const std::string& field) const {
    const std::size_t n = particles.ownedCount();
    const auto* x = static_cast<const double*>(particles.field(field).data());
    return std::vector<double>(x, x + n * std::size_t(dimension_));
}

std::string Decomposition::cutField(const ParticleSetBase& particles) {
    return particles.hasField("referencePosition") ? "referencePosition" : "position";
}

void Decomposition::distribute(ParticleSetBase& particles, const std::string& source) {
    const std::size_t total = particles.size();
    const std::size_t ranks = std::size_t(Communicator::size());
    if (total < ranks)
        throw InputError(source + " holds " + std::to_string(total) + " particles, fewer than the " +
                         std::to_string(ranks) + " ranks of this run: the domain cannot be split; run on at most " +
                         std::to_string(std::max<std::size_t>(total, 1)) + " ranks");
    // Each rank starts from a contiguous block of the file, then Zoltan cuts the space.
    const std::size_t r = std::size_t(Communicator::rank());
    std::vector<std::size_t> block;
    for (std::size_t i = r * total / ranks; i < (r + 1) * total / ranks; ++i) block.push_back(i);
    particles.keep(block);  // the next global id stays that of the whole set, on every rank
    const std::vector<double> ones(particles.ownedCount(), 1.0);
    const auto& id = particles.requireField<std::int64_t>("globalId");
    const std::vector<int> destination = partitioner_->partition(
        coordinates(particles, cutField(particles)), ones, std::vector<std::int64_t>(id.begin(), id.end()));
    sendTo(particles, destination);
    ++rebalances_;
}

bool Decomposition::migrate(ParticleSetBase& particles, const std::vector<double>& weights) {
    const std::size_t n = particles.ownedCount();
    std::vector<double> w = weights;
    if (w.size() != n) w.assign(n, 1.0);
    const double mine = LocalReduce::sum<double>(n, [&](std::size_t i) { return w[i]; });
    std::vector<double> perRank(std::size_t(Communicator::size()));
    Communicator::allGather(&mine, sizeof mine, perRank.data());
    const double mean = std::accumulate(perRank.begin(), perRank.end(), 0.0) / double(perRank.size());
    const double heaviest = *std::max_element(perRank.begin(), perRank.end());
    std::vector<int> destination(n);
    const std::vector<double> x = coordinates(particles);
    bool rebalanced = false;
    if (mean > 0 && heaviest / mean > settings_.maxImbalance) {
        const auto& id = particles.requireField<std::int64_t>("globalId");
        destination = partitioner_->partition(x, w, std::vector<std::int64_t>(id.begin(), id.begin() + long(n)));
        rebalanced = true;
        ++rebalances_;
    } else {
        for (std::size_t i = 0; i < n; ++i) destination[i] = partitioner_->owner(&x[i * std::size_t(dimension_)]);
    }
    const double leaving = double(std::count_if(destination.begin(), destination.end(),
                                                [](int d) { return d != Communicator::rank(); }));
    const double moved = globalSum(leaving);
    if (moved > 0) sendTo(particles, destination);
    ++migrations_;
    return moved > 0 || rebalanced;
}

void Decomposition::sendTo(ParticleSetBase& particles, const std::vector<int>& destination) {
    checkSameFields(particles);
    const int me = Communicator::rank();
    const std::size_t ranks = std::size_t(Communicator::size());
    const std::size_t n = particles.ownedCount();
    std::size_t particleBytes = 0;
    for (const auto& f : particles.fields()) particleBytes += f->elementBytes();
    std::vector<std::vector<char>> send(ranks);
    std::vector<std::size_t> staying;
    for (std::size_t i = 0; i < n; ++i) {
        if (destination[i] == me) {
            staying.push_back(i);
            continue;
        }
        std::vector<char>& buffer = send[std::size_t(destination[i])];
        for (const auto& f : particles.fields()) {
            const std::size_t bytes = f->elementBytes();
            const char* from = static_cast<const char*>(f->data()) + i * bytes;
            buffer.insert(buffer.end(), from, from + bytes);
        }
    }
    const std::vector<std::vector<char>> received = Communicator::allToAll(send);
    particles.keep(staying);
    std::size_t arriving = 0;
    for (const auto& buffer : received) arriving += buffer.size() / particleBytes;
    std::size_t at = particles.appendMigrated(arriving);
    for (const auto& buffer : received) {
        const char* from = buffer.data();
        for (std::size_t k = 0; k < buffer.size() / particleBytes; ++k, ++at)
            for (const auto& f : particles.fields()) {
                const std::size_t bytes = f->elementBytes();
                std::memcpy(static_cast<char*>(f->data()) + at * bytes, from, bytes);
                from += bytes;
            }
    }
    sortByGlobalId(particles);
}

void Decomposition::sortByGlobalId(ParticleSetBase& particles) const {
    const auto& id = particles.requireField<std::int64_t>("globalId");
    std::vector<std::size_t> order(particles.ownedCount());
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (std::is_sorted(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; }))
        return;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
    particles.reorder(order);
}

void Decomposition::planHalo(const ParticleSetBase& particles, double width, const std::string& coordinates) {
    width_ = width;
    const int me = Communicator::rank();
    const std::size_t ranks = std::size_t(Communicator::size());
    const std::size_t n = particles.ownedCount();
    const auto* x = static_cast<const double*>(particles.field(coordinates).data());
    std::vector<std::vector<std::size_t>> perRank(ranks);
    double lo[3], hi[3];
    for (std::size_t i = 0; i < n; ++i) {
        for (int d = 0; d < dimension_; ++d) {
            lo[d] = x[i * std::size_t(dimension_) + std::size_t(d)] - width;
            hi[d] = x[i * std::size_t(dimension_) + std::size_t(d)] + width;
        }
        for (int r : partitioner_->ranksTouching(lo, hi))
            if (r != me) perRank[std::size_t(r)].push_back(i);
    }
    std::vector<long long> sendCounts(ranks), receiveCounts(ranks);
    for (std::size_t r = 0; r < ranks; ++r) sendCounts[r] = (long long)perRank[r].size();
    // Every rank learns what it receives from each: one all-gather of the count matrix's rows.
    std::vector<long long> matrix(ranks * ranks);
    Communicator::allGather(sendCounts.data(), ranks * sizeof(long long), matrix.data());
    for (std::size_t r = 0; r < ranks; ++r) receiveCounts[r] = matrix[r * ranks + std::size_t(me)];
    sendRanks_.clear(), sendIndices_.clear(), receiveRanks_.clear(), receiveCounts_.clear();
    haloSize_ = 0;
    for (std::size_t r = 0; r < ranks; ++r) {
        if (!perRank[r].empty()) {
            sendRanks_.push_back(int(r));
            sendIndices_.push_back(std::move(perRank[r]));
        }
        if (receiveCounts[r] > 0) {
            receiveRanks_.push_back(int(r));
            receiveCounts_.push_back(std::size_t(receiveCounts[r]));
            haloSize_ += std::size_t(receiveCounts[r]);
        }
    }
}

std::size_t Decomposition::appendHalo(ParticleSetBase& particles, const std::vector<std::string>& fields) const {
    particles.appendHalo(haloSize_, *this);
    FieldBase& id = particles.field("globalId");
    refresh(id.data(), id.elementBytes(), particles.haloBegin());
    for (const std::string& name : fields) {
        if (name == "globalId") continue;
        FieldBase& f = particles.field(name);
        refresh(f.data(), f.elementBytes(), particles.haloBegin());
    }
    return haloSize_;
}

void Decomposition::refresh(void* data, std::size_t elementBytes, std::size_t first) const {
    std::vector<std::vector<char>> send(sendRanks_.size()), receive(receiveRanks_.size());
    for (std::size_t k = 0; k < sendRanks_.size(); ++k) {
        send[k].resize(sendIndices_[k].size() * elementBytes);
        char* to = send[k].data();
        for (std::size_t i : sendIndices_[k]) {
            std::memcpy(to, static_cast<const char*>(data) + i * elementBytes, elementBytes);
            to += elementBytes;
        }
        bytesSent_ += send[k].size();
    }
    for (std::size_t k = 0; k < receiveRanks_.size(); ++k) receive[k].resize(receiveCounts_[k] * elementBytes);
    Communicator::exchange(sendRanks_, send, receiveRanks_, receive);
    char* to = static_cast<char*>(data) + first * elementBytes;
    for (const auto& buffer : receive) {
        if (!buffer.empty()) std::memcpy(to, buffer.data(), buffer.size());
        to += buffer.size();
    }
    ++refreshes_;
    messagesSent_ += sendRanks_.size();
}

std::vector<std::string> Decomposition::summary(const ParticleSetBase& particles, double evaluations,
                                               const std::string& evaluation) const {
    const double ranks = globalSum(1.0);
    const double owned = globalSum(double(particles.ownedCount()));
    const double halo = globalSum(double(haloSize_));
    const double bytes = globalSum(double(bytesSent_));
    const double messages = globalSum(double(messagesSent_));
    evaluations = std::max(1.0, evaluations);
    char line[240];
    std::vector<std::string> lines;
    std::snprintf(line, sizeof line,
                  "decomposition        %.0f ranks (%s), %d migrations, %d partitions; halo %.0f particles "
                  "(%.3g of the owned)",
                  ranks, partitioner_->method().c_str(), migrations_, rebalances_, halo,
                  owned > 0 ? halo / owned : 0.0);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line,
                  "halo traffic         %.4g bytes per particle and %.3g messages per rank per %s (%.0f)",
                  owned > 0 ? bytes / owned / evaluations : 0.0, messages / ranks / evaluations, evaluation.c_str(),
                  evaluations);
    lines.emplace_back(line);
    return lines;
}

std::string Decomposition::report(const ParticleSetBase& particles, const std::vector<double>& weights) const {
    struct Row {
        double owned, halo, weight;
    };
    const std::size_t n = particles.ownedCount();
    Row mine{double(n), double(haloSize_), 0};
    for (std::size_t i = 0; i < n; ++i) mine.weight += weights.size() == n ? weights[i] : 1.0;
    std::vector<Row> all(std::size_t(Communicator::size()));
    Communicator::allGather(&mine, sizeof mine, all.data());
    double meanWeight = 0;
    for (const Row& row : all) meanWeight += row.weight / double(all.size());
    std::ostringstream s;
    char line[160];
    std::snprintf(line, sizeof line, "Decomposition (%s, %d ranks, halo width %.4g):\n", settings_.method.c_str(),
                  Communicator::size(), width_);
    s << line;
    for (std::size_t r = 0; r < all.size(); ++r) {
        std::snprintf(line, sizeof line, "    rank %-4zu particles %-10.0f halo %-10.0f load %.3f of the mean\n", r,
                      all[r].owned, all[r].halo, meanWeight > 0 ? all[r].weight / meanWeight : 1.0);
        s << line;
    }
    return s.str();
}

}  // namespace mfdyn
