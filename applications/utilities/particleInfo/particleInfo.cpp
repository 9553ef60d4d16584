// particleInfo: what a particle file holds, without opening ParaView: dimension, particle
// count, particles per region, and for each field its kind and the range of each component
// (and of the magnitude, for vectors). Used to check a particleGen result or a restart state.
//
// Ranges are over the finite values; NaN and infinite values are counted and reported apart
// (with the first particle holding one), since a min/max reduction skips NaN silently and
// particleInfo is where one looks for them. The reader has checked the file (sizes, region ids)
// before anything here allocates from it.
#include "core/Application.hpp"
#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "particles/ParticleSetBase.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/TimeDirectoryReader.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace mfdyn;

namespace {

std::string format(const char* fmt, auto... args) {
    char line[512];
    std::snprintf(line, sizeof line, fmt, args...);
    return line;
}

std::string timeToRead(const Arguments& args) {
    if (args.has("time") && args.has("latestTime")) throw InputError("give -time or -latestTime, not both");
    if (auto name = args.find("time")) return *name;
    const auto times = listTimeDirectories(args.caseDir());
    if (times.empty()) throw InputError("no time directories in case '" + args.caseDir().string() + "'");
    return times.back().second;
}

void printRange(const std::string& label, const std::string& kind, double lo, double hi) {
    std::cout << format("    %-22s %-10s %-24.17g %-24.17g\n", label.c_str(), kind.c_str(), lo, hi);
}

// Component c of particle i, or of its magnitude for c == components() of a vector.
double valueOf(const FieldBase& f, std::size_t i, int c) {
    if (c < f.components()) return f.component(i, c);
    double s = 0;
    for (int k = 0; k < f.components(); ++k) s += f.component(i, k) * f.component(i, k);
    return std::sqrt(s);
}

// Finite range of one component; the non-finite values are counted into `bad` (and the first
// particle with one kept in `first`).
void printComponent(const FieldBase& f, int c, const std::string& label, const std::string& kind,
                    std::size_t& bad, std::size_t& first) {
    const std::size_t n = f.size();
    const double lo = LocalReduce::min(n, [&](std::size_t i) {
        const double v = valueOf(f, i, c);
        return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
    });
    const double hi = LocalReduce::max(n, [&](std::size_t i) {
        const double v = valueOf(f, i, c);
        return std::isfinite(v) ? v : -std::numeric_limits<double>::infinity();
    });
    const std::size_t nonFinite = LocalReduce::sum<std::size_t>(
        n, [&](std::size_t i) { return std::size_t(!std::isfinite(valueOf(f, i, c))); });
    if (nonFinite > 0) {
        for (std::size_t i = 0; i < std::min(first, n); ++i)
            if (!std::isfinite(valueOf(f, i, c))) {
                first = i;
                break;
            }
        bad += nonFinite;
    }
    if (nonFinite == n)
        std::cout << format("    %-22s %-10s %-24s %-24s\n", label.c_str(), kind.c_str(), "(none finite)",
                            "");
    else
        printRange(label, kind, lo, hi);
}

void printField(const FieldBase& f, std::vector<std::string>& warnings) {
    const std::size_t n = f.size();
    const std::string kind = kindName(f.kind());
    if (f.isInteger()) {
        // Over the integers themselves: int64 ids beyond 2^53 would blur as doubles.
        const auto* v = static_cast<const std::int64_t*>(f.data());
        std::int64_t lo = std::numeric_limits<std::int64_t>::max(),
                     hi = std::numeric_limits<std::int64_t>::min();
        for (std::size_t i = 0; i < n; ++i) {
            lo = std::min(lo, v[i]);
            hi = std::max(hi, v[i]);
        }
        std::cout << format("    %-22s %-10s %-24lld %-24lld\n", f.name().c_str(), kind.c_str(),
                            (long long)lo, (long long)hi);
        return;
    }
    const auto names = componentNames(f.kind(), f.dimension());
    std::size_t bad = 0, first = n;
    for (int c = 0; c < f.components(); ++c) {
        const std::string label = names[c].empty() ? f.name() : f.name() + "." + names[c];
        printComponent(f, c, label, c == 0 ? kind : "", bad, first);
    }
    if (f.kind() == FieldKind::vector) {
        // The magnitude of a vector with a NaN component is NaN: already counted above.
        std::size_t ignored = 0, alsoIgnored = n;
        printComponent(f, f.components(), "|" + f.name() + "|", "", ignored, alsoIgnored);
    }
    if (bad > 0)
        warnings.push_back(format("field '%s' holds %zu NaN or infinite value%s, the first at particle %zu",
                                  f.name().c_str(), bad, bad == 1 ? "" : "s", first));
}

int run(const Arguments& args) {
    const std::string time = timeToRead(args);
    const auto file = timeParticleFile(args.caseDir() / time);
    const ParticleFile data = readTimeParticles(args.caseDir() / time);
    const ParticleSetBase& particles = *data.particles;

    std::cout << "file        " << file.string() << "\n"
              << "dimension   " << particles.dimension() << "\n"
              << "particles   " << particles.size() << "\n";
    if (data.hasTime) std::cout << format("time        %.17g\n", data.time);
    std::cout << "memory      " << particles.bytesPerParticle() << " bytes per particle\n";

    std::cout << "\nregions\n";
    const auto counts = particles.regionCounts();
    for (std::size_t r = 0; r < counts.size(); ++r) {
        const std::string name = r < particles.regionNames.size() ? particles.regionNames[r] : "(unnamed)";
        std::cout << format("    %3zu  %-24s %zu\n", r, name.c_str(), counts[r]);
    }
    if (!particles.materialNames.empty()) {
        std::cout << "\nmaterials\n";
        for (std::size_t m = 0; m < particles.materialNames.size(); ++m)
            std::cout << format("    %3zu  %s\n", m, particles.materialNames[m].c_str());
    }

    std::cout << "\n" << format("    %-22s %-10s %-24s %-24s\n", "field", "kind", "min", "max");
    if (particles.size() == 0) {
        for (const auto& f : particles.fields())
            std::cout << format("    %-22s %-10s\n", f->name().c_str(), kindName(f->kind()).c_str());
        return 0;
    }
    std::vector<std::string> warnings;
    for (const auto& f : particles.fields()) printField(*f, warnings);
    if (!warnings.empty()) {
        std::cout << "\nnon-finite values (left out of the ranges above)\n";
        for (const auto& w : warnings) std::cout << "    " << w << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    ApplicationInfo info{
        "particleInfo",
        "Print the dimension, particle count, particles per region and the range of every field\n"
        "of <case>/<time>/particles.vtp, or of the pieces its particles.pvtp lists (written on several\n"
        "ranks), by default of the latest time.",
        {{"time", "name", "the time directory to read"},
         {"latestTime", "", "read the latest time directory (the default)"}},
        {}};
    return runApplication(argc, argv, info, run);
}
