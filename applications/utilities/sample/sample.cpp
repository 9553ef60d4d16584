// sample: particle fields along lines and at points, from the written time directories.
//
//     sample [-case dir] [-latestTime | -time 0.25 | -time 0.1:0.5]
//
// reads system/sampleDict
//
//     interpolation mls;                  // shepard | mls (Interpolation.hpp)
//     kernel { type wendlandC2; }
//     h 0.02;                             // else the particles' smoothingLength field
//     fields (density velocity);
//     sets
//     {
//         centreline { type line; start (0 0.5 0); end (1 0.5 0); nPoints 101; }
//         gauges     { type points; points ((0.1 0.5 0) (0.9 0.5 0)); }
//     }
//     plot yes;                           // a PNG per line set with gnuplot, when installed
//
// and for each chosen time writes postProcessing/sample/<time>/<set>.csv: distance (line) or
// index (points), x, y, z, then each field's components (velocity_x, velocity_y, ...). Points
// beyond every particle's support get NaN and a warning; with mls, points whose neighbours do
// not span the dimension get the Shepard value and a warning.
#include "core/Application.hpp"
#include "core/Case.hpp"
#include "core/Error.hpp"
#include "core/TimeSelection.hpp"
#include "functionObjects/CsvFile.hpp"
#include "functionObjects/Interpolation.hpp"
#include "functionObjects/SamplingSet.hpp"
#include "particles/ParticleSetBase.hpp"
#include "particles/TimeDirectoryReader.hpp"

#include <cstdlib>
#include <fstream>
#include <iostream>

using namespace mfdyn;

namespace {

// The times chosen on the command line (core/TimeSelection.hpp).
std::vector<TimeDirectory> chosenTimes(const Arguments& args, const Case& runCase) {
    const auto all = runCase.timeDirectories();
    if (all.empty()) throw InputError("no time directories in case '" + runCase.root().string() + "'");
    std::vector<double> values;
    std::vector<std::string> names;
    for (const auto& t : all) {
        values.push_back(t.value);
        names.push_back(t.name);
    }
    std::vector<TimeDirectory> chosen;
    for (std::size_t k : selectTimes(args, values, names, 1e-12, "directory")) chosen.push_back(all[k]);
    return chosen;
}

std::vector<std::string> columnNames(const FieldBase& f) {
    std::vector<std::string> names;
    for (const auto& c : componentNames(f.kind(), f.dimension()))
        names.push_back(c.empty() || f.components() == 1 ? f.name() : f.name() + "_" + c);
    return names;
}

// A gnuplot script drawing each field against distance in its own panel (fields differ in scale
// by orders of magnitude), its components together; one PNG per set. `groups` holds each
// field's first and last CSV column (0-based).
void plot(const std::filesystem::path& csv, const std::vector<std::string>& fields,
          const std::vector<std::pair<std::size_t, std::size_t>>& groups) {
    const auto png = std::filesystem::path(csv).replace_extension(".png");
    const auto script = std::filesystem::path(csv).replace_extension(".gnuplot");
    {
        std::ofstream out(script);
        out << "set terminal pngcairo size 900," << 300 * groups.size() << " noenhanced\nset output '"
            << png.string() << "'\nset datafile separator ','\nset key autotitle columnhead\nset grid\n"
            << "set multiplot layout " << groups.size() << ",1\n";
        for (std::size_t g = 0; g < groups.size(); ++g) {
            out << "set title '" << fields[g] << "'\n"
                << (g + 1 == groups.size() ? "set xlabel 'distance [m]'\n" : "") << "plot";
            for (std::size_t c = groups[g].first; c <= groups[g].second; ++c)
                out << (c > groups[g].first ? "," : "") << " '" << csv.string() << "' using 1:" << c + 1
                    << " with linespoints";
            out << "\n";
        }
        out << "unset multiplot\n";
    }
    const std::string command = "gnuplot '" + script.string() + "' > /dev/null 2>&1";
    if (std::system(command.c_str()) != 0)
        std::cerr << "Warning: gnuplot failed on " << script.string() << "; no plot\n";
    else
        std::cout << "    plot " << png.string() << "\n";
}

int run(const Arguments& args) {
    const Case runCase(args.caseDir());
    const Dictionary dict = runCase.readSystem("sampleDict");
    const auto fields = dict.get<std::vector<std::string>>("fields");
    if (fields.empty()) throw dict.error("fields", "no fields to sample");
    std::vector<SamplingSet> sets;
    const Dictionary& setsDict = dict.subDict("sets");
    for (const auto& name : setsDict.keys()) {
        if (!setsDict.isDict(name)) throw setsDict.error(name, "set '" + name + "' is not a dictionary");
        sets.emplace_back(setsDict.subDict(name), name);
    }
    if (sets.empty()) throw dict.error("sets", "no sets to sample");
    bool plotting = dict.getOrDefault<bool>("plot", false);
    if (plotting && std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        std::cout << "gnuplot not found: no plots\n";
        plotting = false;
    }

    for (const auto& time : chosenTimes(args, runCase)) {
        const auto file = timeParticleFile(runCase.timeDir(time.name));
        const ParticleFile data = readTimeParticles(runCase.timeDir(time.name));
        const ParticleSetBase& particles = *data.particles;
        std::vector<const FieldBase*> chosen;
        for (const auto& name : fields) {
            const FieldBase* f = particles.findField(name);
            if (!f) {
                std::string have;
                for (const auto& n : particles.fieldNames()) have += " " + n;
                std::string message = "no field '" + name + "' in " + file.string() + "; fields:" + have;
                if (auto g = closestMatch(name, particles.fieldNames()); !g.empty())
                    message += " (did you mean '" + g + "'?)";
                throw dict.error("fields", message);
            }
            chosen.push_back(f);
        }
        const Interpolation interpolation(dict, particles);
        std::cout << "time " << time.name << ": " << particles.size() << " particles, "
                  << Interpolation::methodName(interpolation.method()) << " interpolation\n";
        for (const auto& set : sets) {
            const auto stencils = interpolation.stencils(set.points());
            std::vector<std::string> columns{set.coordinateName(), "x", "y", "z"};
            std::vector<std::vector<std::vector<double>>> values;
            std::vector<std::pair<std::size_t, std::size_t>> groups;
            for (const FieldBase* f : chosen) {
                const std::size_t first = columns.size();
                for (const auto& c : columnNames(*f)) columns.push_back(c);
                groups.emplace_back(first, columns.size() - 1);
                values.push_back(Interpolation::apply(stencils, *f));
            }
            std::size_t empty = 0, fallback = 0;
            for (const auto& s : stencils) {
                empty += s.status == Interpolation::Status::noNeighbours;
                fallback += s.status == Interpolation::Status::shepardFallback;
            }
            const auto csvPath = runCase.postProcessing() / "sample" / time.name / (set.name() + ".csv");
            {
                CsvFile csv(csvPath, columns);
                for (std::size_t p = 0; p < stencils.size(); ++p) {
                    std::vector<double> row{set.coordinate()[p], set.points()[p][0], set.points()[p][1],
                                            set.points()[p][2]};
                    for (const auto& v : values) row.insert(row.end(), v[p].begin(), v[p].end());
                    csv.row(row);
                }
            }
            std::cout << "    " << set.name() << ": " << stencils.size() << " points -> " << csvPath.string()
                      << "\n";
            if (empty)
                std::cerr << "Warning: set '" << set.name() << "': " << empty
                          << " points have no particle within reach; their values are NaN\n";
            if (fallback)
                std::cerr << "Warning: set '" << set.name() << "': at " << fallback
                          << " points the neighbours do not span the dimension; Shepard values used\n";
            if (plotting && set.type() == SamplingSet::Type::line) plot(csvPath, fields, groups);
        }
    }
    for (const auto& u : dict.unusedEntries())
        std::cerr << "Warning: " << u.scopedKey << " is never read"
                  << (u.suggestion.empty() ? "" : " (did you mean '" + u.suggestion + "'?)") << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const ApplicationInfo info{"sample",
                               "Particle fields interpolated along lines and at points (system/sampleDict).",
                               {{"time", "t|a:b", "the time, or range of times, to sample (default: all)"},
                                {"latestTime", "", "sample the latest time only"}},
                               {}};
    return runApplication(argc, argv, info, run);
}
