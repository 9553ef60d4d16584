#pragma once
// Particle management of the finite pointset method: particles inserted into holes and close pairs
// merged (doc/methods/fpm.md §3.5: the thesis's code "provides the possibility to add and remove
// particles", its criteria are in Kuhnert 1999 and not given; the rules here are the note's [R],
// engineered here: "ours"). The method and its choices: the opening comment of ParticleManagement.cpp.
#include "core/Tensor.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"
#include "particles/ParticleSet.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mfdyn::fpm {

template <int Dim>
class ParticleManagement {
public:
    struct Options {
        bool insert = false;
        double holeSize = 0.5;  // a hole: no particle within holeSize h of a point inside the body
        bool merge = false;
        double mergeDistance = 0.15;  // a pair closer than mergeDistance h becomes one particle
        // a candidate point y is inside the body when the centre-of-mass offset of its neighbours
        // within h, |sum_j w_j (x_j - y)| / (h sum_j w_j), is at most this (SurfaceDetection's test 1)
        double surfaceOffset = 0.3;
    };

    // What the last apply() did, and the totals of the run.
    struct Counts {
        std::size_t inserted = 0, merged = 0;  // particles inserted; pairs merged (one removed each)
        std::size_t surface = 0;               // hole candidates rejected as beyond a free surface
        std::size_t unfitted = 0;  // hole candidates whose fit failed (too few neighbours) or gave rho <= 0
        double mass = 0;           // the change of the total mass (round-off: mass is redistributed)
        Vector<Dim> momentum = Vector<Dim>::Zero();  // the change of the total momentum sum m v
    };

    explicit ParticleManagement(Options options) : options_(options) {}
    const Options& options() const { return options_; }

    // Merges, then inserts, on the particles' current positions with support radius h and the fit
    // weight of the solver. Needs the fields position, mass, volume and density. Returns, for each
    // particle after, the index it had before (a merged pair: the survivor's), -1 for an inserted one.
    std::vector<std::int64_t> apply(ParticleSet<Dim>& particles, double h, const FitWeight& weight);

    const Counts& last() const { return last_; }
    const Counts& total() const { return total_; }

private:
    void merge(ParticleSet<Dim>& particles, double h, std::vector<std::int64_t>& origin);
    void insert(ParticleSet<Dim>& particles, double h, const FitWeight& weight,
                std::vector<std::int64_t>& origin);

    Options options_;
    Counts last_, total_;
};

}  // namespace mfdyn::fpm
