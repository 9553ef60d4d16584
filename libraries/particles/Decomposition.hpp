#pragma once
// Domain decomposition of a particle set over the ranks of a run (issue 21): which rank owns
// which particles, the particles that move between ranks (migration), and the halo: the other
// ranks' particles this rank's owned ones reach, appended as the first ghosts of the set
// (ParticleSetBase::appendHalo) and refreshed field by field where a phase reads them
// (copyToGhosts). All communication is in Communicator's calls; the space is cut by Zoltan
// (Partitioner.hpp). With one rank nothing here is constructed.
//
// Order, for results that do not depend on the number of ranks: after every migration the owned
// particles are sorted by global id (the serial run's order when the particle file is in id
// order, as particleGen writes it and the readers of pieces sort), and the halo is appended in
// rank order, each rank's part in its owned order.
#include "particles/ParticleSetBase.hpp"
#include "particles/Partitioner.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class Decomposition final : public HaloExchange {
public:
    struct Settings {
        std::string method = "rcb";  // Partitioner::methods()
        // Rebalance at a migration when the heaviest rank's weight over the mean passes this.
        double maxImbalance = 1.2;
    };

    Decomposition(const Settings& settings, int dimension);
    ~Decomposition() override;

    // Collective. Every rank holds the whole set (read from the time directory): keeps this
    // rank's share of a first partition (weight 1 per particle). InputError when the set has
    // fewer particles than there are ranks (`source`: the file, for the message). The cut is of
    // the reference configuration when the set carries one (`referencePosition`: a
    // total-Lagrangian method's restart, whose neighbourhoods and so its halo live there; at a
    // fresh start x = X), else of the positions.
    static std::string cutField(const ParticleSetBase& particles);
    void distribute(ParticleSetBase& particles, const std::string& source);
    // Collective, with no ghosts in the set. Owned particles outside this rank's part go to
    // their owners, every field with them; first a new partition when the weighted imbalance
    // (weights: one per owned particle, such as its neighbour count; empty: 1 each) passes
    // maxImbalance. Returns true when particles moved or the partition changed.
    bool migrate(ParticleSetBase& particles, const std::vector<double>& weights);
    // Collective. The owned particles each other rank needs: those whose box x ± width meets
    // that rank's part (width: the largest interaction radius plus the skin the caller moves
    // within before it migrates again). `coordinates`: the vector field x is read from, the
    // one the parts were cut in (a total-Lagrangian method's halo is planned once, in X).
    void planHalo(const ParticleSetBase& particles, double width,
                  const std::string& coordinates = "position");
    // Appends the halo as ghosts and fills the named fields (globalId always). Returns the
    // number of halo particles.
    std::size_t appendHalo(ParticleSetBase& particles, const std::vector<std::string>& fields) const;
    void refresh(void* data, std::size_t elementBytes, std::size_t first) const override;

    std::size_t haloSize() const { return haloSize_; }
    double width() const { return width_; }
    int migrations() const { return migrations_; }
    int rebalances() const { return rebalances_; }
    // Halo refreshes, their bytes and messages sent by this rank since the start (bench/mpi).
    std::uint64_t refreshes() const { return refreshes_; }
    std::uint64_t bytesSent() const { return bytesSent_; }
    std::uint64_t messagesSent() const { return messagesSent_; }
    // Collective. Per rank: owned particles, halo, weight over the mean; for the log.
    std::string report(const ParticleSetBase& particles, const std::vector<double>& weights) const;
    const Partitioner& partitioner() const { return *partitioner_; }
    // Collective. The summary's two lines (what a weak-scaling model needs, bench/mpi): ranks,
    // migrations, partitions and the halo over the owned particles; the halo bytes per particle
    // and messages per rank per `evaluation` (a rate evaluation, a step: the caller's unit),
    // over all ranks.
    std::vector<std::string> summary(const ParticleSetBase& particles, double evaluations,
                                     const std::string& evaluation) const;

private:
    void sendTo(ParticleSetBase& particles, const std::vector<int>& destination);
    void sortByGlobalId(ParticleSetBase& particles) const;
    std::vector<double> coordinates(const ParticleSetBase& particles,
                                    const std::string& field = "position") const;

    Settings settings_;
    int dimension_;
    std::unique_ptr<Partitioner> partitioner_;
    // The halo plan: owned indices sent to each rank, counts received from each.
    std::vector<int> sendRanks_, receiveRanks_;
    std::vector<std::vector<std::size_t>> sendIndices_;
    std::vector<std::size_t> receiveCounts_;
    std::size_t haloSize_ = 0;
    double width_ = 0;
    int migrations_ = 0, rebalances_ = 0;
    mutable std::uint64_t refreshes_ = 0, bytesSent_ = 0, messagesSent_ = 0;
};

}  // namespace mfdyn
