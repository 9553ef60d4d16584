#pragma once
// What the distributed function-object tests share: a run context whose time a test advances step
// by step, and a particle set spread over the ranks, each rank holding the ids equal to its rank
// (plus a shift) modulo the rank count, in descending id order: a share that a gathered copy must
// both join and sort, and that a shift moves to other ranks as a migration would.
#include "../FunctionObjectTestCase.hpp"
#include "core/Communicator.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mfdyn::distributedTest {

namespace fs = std::filesystem;

inline constexpr std::int64_t total = 23;

// A run context whose time the test advances step by step.
class SteppedContext final : public RunContext {
public:
    explicit SteppedContext(const fs::path& root)
        : case_(root),
          time_(root / "system" / "controlDict",
                Dictionary::parse(functionObjectTest::controlDictText, "controlDict")) {
        time_.start(0, "0");
    }
    const Case& runCase() const override { return case_; }
    const Time& time() const override { return time_; }
    const FieldStore& fields() const override { return particles; }
    const std::string& startTimeName() const override { return start_; }
    void step() { time_.advance(1e-3); }
    ParticleSet<2> particles;

private:
    Case case_;
    Time time_;
    std::string start_ = "0";
};

// Particle `id` at (id, -2 id), mass id/2, region id % 2.
inline void place(ParticleSet<2>& p, const std::vector<std::int64_t>& ids) {
    p.resize(ids.size());
    p.regionNames = {"even", "odd"};
    auto& mass = p.scalarField("mass");
    auto& pressure = p.scalarField("pressure");
    auto& stress = p.symmTensorField("deviatoricStress");
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const auto id = ids[k];
        p.globalId()[k] = id;
        p.region()[k] = id % 2;
        p.position()[k] = Vector<2>(double(id), -2.0 * double(id));
        mass[k] = 0.5 * double(id);
        pressure[k] = 10.0 + double(id);
        stress[k].c[2] = double(id) / 3;
    }
}

// This rank's share of `count` particles: the ids with (id + shift) % ranks equal to its rank, descending.
inline std::vector<std::int64_t> myShare(std::int64_t count = total, std::int64_t shift = 0) {
    std::vector<std::int64_t> ids;
    for (std::int64_t id = count - 1; id >= 0; --id)
        if ((id + shift) % Communicator::size() == Communicator::rank()) ids.push_back(id);
    return ids;
}

inline std::vector<std::int64_t> everyId() {
    std::vector<std::int64_t> ids;
    for (std::int64_t id = 0; id < total; ++id) ids.push_back(id);
    return ids;
}

}  // namespace mfdyn::distributedTest
