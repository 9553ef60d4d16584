// particleCompare: two particle states side by side, particle by particle (matched by global id),
// field by field: the largest difference, relative to the field's scale (its largest magnitude in
// the reference), and whether the field is the same to the bit. For the distributed runs' check
// that 1, 2, 3 and 4 ranks give the serial answer (issue 21), a restart against an uninterrupted
// run, or any two runs a user wants to tell apart. Exit status 1 when a field differs by more
// than -tolerance, or the particles or fields are not the same.
#include "core/Application.hpp"
#include "core/Error.hpp"
#include "particles/ParticleSetBase.hpp"
#include "particles/TimeDirectoryReader.hpp"
#include "particles/VtpReader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

// A time directory (its particles.vtp, or the pieces of its particles.pvtp) or one file.
std::unique_ptr<ParticleSetBase> readState(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return std::move(readTimeParticles(path).particles);
    if (!fs::exists(path, ec)) throw InputError("particleCompare: no file or time directory '" + path + "'");
    return std::move(readVtp(path).particles);
}

// Indices of the particles in global-id order; InputError on a repeated id.
std::vector<std::size_t> idOrder(const ParticleSetBase& set, const std::string& path) {
    const auto& id = set.requireField<std::int64_t>("globalId");
    std::vector<std::size_t> order(set.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
    for (std::size_t k = 1; k < order.size(); ++k)
        if (id[order[k]] == id[order[k - 1]])
            throw InputError(path + ": global id " + std::to_string(id[order[k]]) + " appears twice");
    return order;
}

int run(const Arguments& args) {
    const std::string pathA = args.positional()[0], pathB = args.positional()[1];
    double tolerance = 1e-12;
    if (auto t = args.find("tolerance")) {
        char* end = nullptr;
        tolerance = std::strtod(t->c_str(), &end);
        if (end == t->c_str() || *end != '\0' || !(tolerance >= 0))
            throw InputError("-tolerance '" + *t + "' is not a non-negative number");
    }
    const auto a = readState(pathA), b = readState(pathB);
    if (a->dimension() != b->dimension())
        throw InputError("the states differ in dimension: " + std::to_string(a->dimension()) + "D (" + pathA +
                         ") and " + std::to_string(b->dimension()) + "D (" + pathB + ")");
    const auto orderA = idOrder(*a, pathA), orderB = idOrder(*b, pathB);
    const auto& idA = a->requireField<std::int64_t>("globalId");
    const auto& idB = b->requireField<std::int64_t>("globalId");
    bool same = orderA.size() == orderB.size();
    for (std::size_t k = 0; same && k < orderA.size(); ++k) same = idA[orderA[k]] == idB[orderB[k]];
    if (!same) {
        std::cout << "The particles differ: " << orderA.size() << " in " << pathA << ", " << orderB.size() << " in "
                  << pathB << ", not the same global ids\n";
        return 1;
    }
    int failures = 0;
    std::printf("%-34s %-12s %-12s %-12s %s\n", "field", "max |a - b|", "scale", "relative", "");
    for (const auto& fa : a->fields()) {
        const FieldBase* fb = b->findField(fa->name());
        if (!fb || fb->kind() != fa->kind()) {
            std::printf("%-34s only in %s\n", fa->name().c_str(), pathA.c_str());
            ++failures;
            continue;
        }
        const int components = fa->components();
        double largest = 0, scale = 0;
        std::int64_t worst = -1;
        bool bitwise = true;
        for (std::size_t k = 0; k < orderA.size(); ++k)
            for (int c = 0; c < components; ++c) {
                const double va = fa->component(orderA[k], c), vb = fb->component(orderB[k], c);
                scale = std::max(scale, std::abs(va));
                const double d = std::abs(va - vb);
                if (std::memcmp(&va, &vb, sizeof va) != 0) bitwise = false;
                if (d > largest || (std::isnan(d) && worst < 0)) largest = d, worst = idA[orderA[k]];
            }
        const double relative = scale > 0 ? largest / scale : largest;
        const bool fails = !(relative <= tolerance);
        failures += fails;
        std::printf("%-34s %-12.4e %-12.4e %-12.4e %s\n", fa->name().c_str(), largest, scale, relative,
                    bitwise ? "bit-identical" : (fails ? ("FAILS (worst: particle " + std::to_string(worst) + ")").c_str()
                                                       : ""));
    }
    for (const auto& fb : b->fields())
        if (!a->findField(fb->name())) {
            std::printf("%-34s only in %s\n", fb->name().c_str(), pathB.c_str());
            ++failures;
        }
    if (failures) {
        std::cout << failures << " field(s) differ by more than " << tolerance << " relative, or are missing\n";
        return 1;
    }
    std::cout << "Same to " << tolerance << " relative in every field (" << orderA.size() << " particles)\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    ApplicationInfo info{
        "particleCompare",
        "Compare two particle states (time directories or .vtp files) particle by particle, matched by\n"
        "global id: for each field the largest difference relative to the field's largest magnitude in\n"
        "<a>, and whether it is the same to the bit. Exit status 1 when a field differs by more than\n"
        "-tolerance (default 1e-12) or the particles differ.",
        {{"tolerance", "value", "the largest relative difference accepted (default 1e-12)"}},
        {"a", "b"},
        false};
    return runApplication(argc, argv, info, run);
}
