// orderEstimate: the observed order of convergence of particle fields from three runs of one case
// at increasing particle counts N1 < N2 < N3, by the three-resolution estimate of von Nida 2005,
// "Numerical simulation of elastic solids with the finite pointset method", §7.2.3, Lemma 7.1
// (after Deuflhard & Hohmann, "Numerical Analysis in Modern Scientific Computing"); the equations,
// their derivation and the numerics are in OrderEstimate.cpp, the method note's summary in
// doc/methods/fpm.md §4.11.
//
//     orderEstimate [-case dir] [-latestTime | -time 0.5 | -time 0.5:2]
//
// reads system/orderEstimateDict of the study's directory:
//
//     runs          (coarse medium fine);  // three case directories, relative to this one, by N
//     fields        (density pressure);    // particle fields to compare
//     norm          infinity;              // infinity | l2 (root mean square over the points)
//     grid          { spacing 0.5; }       // the comparison grid G: multiples of spacing
//     interior      0.9;                   // least Shepard kernel sum for a point of G to count
//     interpolation mls;                   // shepard | mls (default mls)
//     kernel        { type wendlandC2; }   // the interpolation kernel (default wendlandC2)
//     h             (3.75 3.0 2.25);       // each run's smoothing length (default: its
//                                          // particles' smoothingLength field)
//     positionField position;              // referencePosition: compare in the reference configuration
//
// At each time that all three runs wrote (matched by value to 1e-9 relative; a time that only
// some runs have is skipped, with one warning naming them all) each run's particles.vtp (or the
// pieces of its particles.pvtp, a run on several ranks) is read
// and its fields are interpolated (functionObjects/Interpolation.hpp, as `sample` does) onto the
// grid points x = spacing (i, j, k) inside the intersection of the three runs' bounding boxes.
// A point counts where, in every run, the Shepard kernel sum
//
//     S(x) = sum_j V_j W(|x - x_j|, h_j)     (about 1 inside a body, 0.5 on its surface)
//
// is at least `interior`, and the interpolation is determined (mls: the neighbours span the
// dimension); so points near any run's surface, where the interpolation is one-sided and least
// accurate, are left out. Over those points, for each field component,
//
//     d21 = ||phi2 - phi1||,  d32 = ||phi3 - phi2||,  ratio = d32 / d21,  alpha(order) = ratio.
//
// Vector and tensor fields are estimated component by component (velocity_x, velocity_y, ...; a
// tensor's as `sample` names them, e.g. stress_xy), each with its own order: a component that is
// zero by symmetry gives an undefined order rather than spoiling the others. Integer fields
// (region, globalId) are refused.
//
// V_j is mass/density where both fields exist (as the interpolation takes it), else the `volume`
// field, else the bounding box volume / N (said in the summary). The mean mesh size of each run
// is dx = (sum_j V_j / N)^(1/d) at the first time compared.
//
// Writes postProcessing/orderEstimate/orderEstimate.csv: time, points, then per field component
// <name>_d21, <name>_d32, <name>_ratio, <name>_order (NaN where the order is outside [-10, 20]
// or undefined: d21 zero or within 1e-10 of the values, i.e. round-off). The file is this invocation's table, written whole through a temporary file and
// a rename (not continued across invocations as a solver's CsvFile series is: the summary below
// must describe exactly its rows). The summary (N, dx, each field's time-averaged, least and
// largest order, and the times left out and why) is printed and written to
// postProcessing/orderEstimate/summary.txt.
//
// Input errors (exit status 1, at the dictionary's file and line): not three runs, a run directory
// missing or without time directories, particle counts not strictly increasing coarse to fine, a
// field missing in a run (its fields listed), no time common to the runs, no grid point inside all
// three bodies at any time (a single such time is skipped with a warning), and any entry that is
// not a keyword (with a did-you-mean).
#include "OrderEstimate.hpp"
#include "core/Application.hpp"
#include "core/Case.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Log.hpp"
#include "core/TimeSelection.hpp"
#include "functionObjects/Interpolation.hpp"
#include "kernels/Kernel.hpp"
#include "particles/ParticleSetBase.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/TimeDirectoryReader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

constexpr const char* dictName = "orderEstimateDict";
const std::array<const char*, 3> runRoles{"coarse", "medium", "fine"};
// Times of the three runs are the same when they agree to this, relative: the runs write at the
// same nominal times, but a time accumulated from different step sizes differs in its last digits.
constexpr double timeTolerance = 1e-9;
// A grid of more points than this is a spacing given in the wrong unit, not a study.
constexpr double maxGridPoints = 5e7;

KeywordSchema gridKeywords() {
    return KeywordSchema("utility", "orderEstimate grid")
        .scalar("spacing", "m", "distance between the comparison points along each axis")
        .greaterThan(0);
}

KeywordSchema orderEstimateKeywords() {
    return KeywordSchema("utility", "orderEstimate")
        .words("runs", "the three runs' case directories, relative to this case, coarse to fine")
        .words("fields", "the particle fields to compare (vectors and tensors component by component)")
        .word("norm", {"infinity", "l2"}, "the norm of the differences over the grid points (l2: RMS)")
        .orDefault("infinity")
        .dictionary("grid", "the regular comparison grid")
        .nested(&gridKeywords)
        .scalar("interior", "-", "least Shepard kernel sum sum_j V_j W (about 1 inside, 0.5 on a surface)")
        .greaterThan(0)
        .orDefault(0.9)
        .word("interpolation", {"shepard", "mls"},
              "shepard (kernel-weighted average) or mls (first-order moving least squares)")
        .orDefault("mls")
        .dictionary("kernel", "the interpolation kernel (default { type wendlandC2; })")
        .optional()
        .vector("h", "m",
                "each run's smoothing length, coarse to fine; default: each run's smoothingLength field")
        .ofLength(3)
        .greaterThan(0)
        .optional()
        .identifier("positionField",
                    "vector field of the particles' coordinates (referencePosition: reference)")
        .orDefault("position");
}

std::string number(double x, const char* format = "%.10g") {
    char text[40];
    std::snprintf(text, sizeof text, format, x);
    return text;
}

// Every entry of the dictionary must be a keyword: a misspelt `nrom l2;` would otherwise give
// the default norm's orders without a word.
void refuseUnknownEntries(const Dictionary& dict) {
    const auto unused = dict.unusedEntries();
    if (unused.empty()) return;
    const KeywordSchema schema = orderEstimateKeywords(), grid = gridKeywords();  // alive while listed
    std::vector<std::string> keywords, gridNames;
    for (const auto& k : schema.keywords()) keywords.push_back(k.name);
    for (const auto& k : grid.keywords()) gridNames.push_back(k.name);
    std::string message = std::to_string(unused.size()) + " unknown " +
                          (unused.size() == 1 ? "entry" : "entries") + " in " + dictName + " (keywords:";
    for (const auto& k : keywords) message += " " + k;
    message += "; grid { spacing })";
    for (const auto& u : unused) {
        // The dictionary suggests among the keys asked for and missing; a misspelling of a
        // keyword that was also given (`nrom` beside `norm`) is matched against the schema.
        std::string suggestion = u.suggestion;
        if (suggestion.empty() && u.scopedKey.find('/') == std::string::npos)
            suggestion = closestMatch(u.scopedKey, keywords);
        else if (suggestion.empty() && u.scopedKey.rfind("grid/", 0) == 0)
            suggestion = closestMatch(u.scopedKey.substr(5), gridNames);
        message += "\n    " + u.where.str() + ": '" + u.scopedKey + "'" +
                   (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)");
    }
    throw InputError(unused.front().where, "", message);
}

struct Run {
    std::string name;  // as given in `runs`
    fs::path dir;
    std::vector<TimeDirectory> times;  // those holding particles.vtp or particles.pvtp
};

// One time written by all three runs: its value in the coarse run and each run's directory name.
struct CommonTime {
    double value;
    std::array<std::string, 3> names;
};

bool sameTime(double a, double b) {
    return std::abs(a - b) <= timeTolerance * std::max(std::abs(a), std::abs(b));
}

// The times all three runs have; the others are named in one warning.
std::vector<CommonTime> commonTimes(const std::array<Run, 3>& runs) {
    std::vector<CommonTime> common;
    std::array<std::vector<bool>, 3> matched;
    for (int k = 0; k < 3; ++k) matched[k].assign(runs[k].times.size(), false);
    for (std::size_t i = 0; i < runs[0].times.size(); ++i) {
        CommonTime t{runs[0].times[i].value, {runs[0].times[i].name, "", ""}};
        std::array<std::size_t, 3> index{i, 0, 0};
        bool inAll = true;
        for (int k = 1; k < 3 && inAll; ++k) {
            inAll = false;
            for (std::size_t j = 0; j < runs[k].times.size() && !inAll; ++j)
                if (!matched[k][j] && sameTime(t.value, runs[k].times[j].value)) {
                    inAll = true;
                    index[k] = j;
                    t.names[k] = runs[k].times[j].name;
                }
        }
        if (!inAll) continue;
        for (int k = 0; k < 3; ++k) matched[k][index[k]] = true;
        common.push_back(t);
    }
    // The unmatched times, each once with the runs that have it.
    std::vector<std::pair<double, std::string>> partial;
    for (int k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < runs[k].times.size(); ++j) {
            if (matched[k][j]) continue;
            const double value = runs[k].times[j].value;
            auto same = std::find_if(partial.begin(), partial.end(),
                                     [&](const auto& p) { return sameTime(p.first, value); });
            if (same == partial.end())
                partial.emplace_back(value, runs[k].times[j].name + " (" + runs[k].name);
            else
                same->second += ", " + runs[k].name;
        }
    if (!partial.empty()) {
        std::sort(partial.begin(), partial.end());
        std::string list;
        for (const auto& p : partial) list += (list.empty() ? "" : "; ") + p.second + ")";
        Log::warning(std::to_string(partial.size()) + " time" + (partial.size() == 1 ? " is" : "s are") +
                     " not written by all three runs and skipped: " + list);
    }
    return common;
}

// The common times chosen on the command line, as `sample` chooses (core/TimeSelection.hpp).
std::vector<CommonTime> chosenTimes(const Arguments& args, const std::vector<CommonTime>& all) {
    std::vector<double> values;
    std::vector<std::string> names;
    for (const auto& t : all) {
        values.push_back(t.value);
        names.push_back(t.names[0]);
    }
    std::vector<CommonTime> chosen;
    for (std::size_t k : selectTimes(args, values, names, timeTolerance, "of all three runs"))
        chosen.push_back(all[k]);
    return chosen;
}

// A field component compared: the field and which of its components.
struct Column {
    std::string name;  // density, velocity_x
    std::string field;
    int component;
};

// " density mass position ...": the particles' fields (only the real-valued ones with realOnly).
std::string fieldList(const ParticleSetBase& particles, bool realOnly = false) {
    std::string list;
    for (const auto& n : particles.fieldNames())
        if (!realOnly || !particles.findField(n)->isInteger()) list += " " + n;
    return list;
}

// The columns the fields give, checked in one run's particles.
std::vector<Column> columnsOf(const std::vector<std::string>& fields, const ParticleSetBase& particles,
                              const fs::path& file, const KeywordValues& values) {
    std::vector<Column> columns;
    for (const auto& name : fields) {
        const FieldBase* f = particles.findField(name);
        if (!f) {
            std::string message =
                "no field '" + name + "' in " + file.string() + "; fields:" + fieldList(particles);
            if (auto guess = closestMatch(name, particles.fieldNames()); !guess.empty())
                message += " (did you mean '" + guess + "'?)";
            throw values.error("fields", message);
        }
        if (f->isInteger())
            throw values.error("fields", "field '" + name + "' in " + file.string() +
                                             " holds integers (an id or a count), which have no order of "
                                             "convergence; real fields:" +
                                             fieldList(particles, true));
        const auto components = componentNames(f->kind(), f->dimension());
        for (int c = 0; c < f->components(); ++c)
            columns.push_back(
                {f->components() == 1 ? name : name + "_" + components[std::size_t(c)], name, c});
    }
    return columns;
}

// One run at one time: its particles, interpolation and what the kernel sum needs.
struct RunState {
    fs::path file;
    ParticleFile data;
    std::unique_ptr<Interpolation> interpolation;
    std::vector<SamplePoint> position;  // the positionField, zero-padded
    std::vector<double> h;              // per particle, as the interpolation takes it
    std::vector<double> volume;         // V_j
    std::vector<Column> columns;        // the fields' components, checked in these particles
    std::string volumeSource;           // "mass/density", "volume field", "bounding box / N"
    double totalVolume = 0.0;
    SamplePoint lo{0, 0, 0}, hi{0, 0, 0};  // bounding box of the positions
    const ParticleSetBase& particles() const { return *data.particles; }
};

RunState loadRun(const Run& run, const std::string& timeName, const Dictionary& dict,
                 const KeywordValues& values, const std::vector<std::string>& fields, int runIndex) {
    RunState s;
    s.file = timeParticleFile(run.dir / timeName);
    s.data = readTimeParticles(run.dir / timeName);
    const ParticleSetBase& particles = s.particles();
    const std::size_t n = particles.size();
    const int dim = particles.dimension();
    if (n == 0) throw InputError(s.file.string() + " holds no particles");
    // What the user asked for is checked before the interpolation is built, so that a missing
    // field or position is reported as such and not as the interpolation's complaint.
    s.columns = columnsOf(fields, particles, s.file, values);
    const FieldBase* position = particles.findField(values.word("positionField"));
    if (!position || position->kind() != FieldKind::vector)
        throw values.error("positionField", "no vector field '" + values.word("positionField") + "' in " +
                                                s.file.string() + "; fields:" + fieldList(particles));
    if (!values.given("h") && !particles.findField("smoothingLength"))
        throw values.error("runs", s.file.string() +
                                       " has no smoothingLength field: give each run's smoothing length as "
                                       "h (h1 h2 h3)");

    // The interpolation reads its keywords from a copy of the dictionary with this run's h.
    Dictionary runDict = dict;
    runDict.set("interpolation", values.word("interpolation"));
    runDict.set("positionField", values.word("positionField"));
    if (values.given("h"))
        runDict.set("h", number(values.vector("h")[std::size_t(runIndex)], "%.17g"));
    else
        runDict.remove("h");
    s.interpolation = std::make_unique<Interpolation>(runDict, particles);

    s.position.assign(n, SamplePoint{0, 0, 0});
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < dim; ++c) s.position[i][c] = position->component(i, c);
    for (int c = 0; c < dim; ++c) {
        s.lo[c] = HUGE_VAL;
        s.hi[c] = -HUGE_VAL;
        for (const auto& x : s.position) {
            s.lo[c] = std::min(s.lo[c], x[c]);
            s.hi[c] = std::max(s.hi[c], x[c]);
        }
    }

    if (values.given("h")) {
        s.h.assign(n, values.vector("h")[std::size_t(runIndex)]);
    } else {
        const FieldBase& smoothingLength = *particles.findField("smoothingLength");  // checked above
        s.h.resize(n);
        for (std::size_t i = 0; i < n; ++i) s.h[i] = smoothingLength.component(i, 0);
    }

    // The volumes the interpolation weights with, so that S(x) is the sum it forms.
    const FieldBase* mass = particles.findField("mass");
    const FieldBase* density = particles.findField("density");
    const FieldBase* volume = particles.findField("volume");
    s.volume.resize(n);
    if (mass && density) {
        for (std::size_t i = 0; i < n; ++i) s.volume[i] = mass->component(i, 0) / density->component(i, 0);
        s.volumeSource = "mass/density";
    } else if (volume) {
        for (std::size_t i = 0; i < n; ++i) s.volume[i] = volume->component(i, 0);
        s.volumeSource = "the volume field";
    } else {
        // The particles' bounding box underestimates a body's volume by about one spacing per
        // side: S(x) comes out a little low, and dx a little small, which the message says.
        double box = 1.0;
        for (int c = 0; c < dim; ++c) box *= s.hi[c] - s.lo[c];
        s.volume.assign(n, box / double(n));
        s.volumeSource = "the bounding box volume / N (no mass and density, no volume field)";
    }
    for (double v : s.volume) s.totalVolume += v;
    if (!(s.totalVolume > 0.0) || !std::isfinite(s.totalVolume))
        throw InputError(s.file.string() + ": the particles' volumes (" + s.volumeSource + ") sum to " +
                         number(s.totalVolume) + "; the kernel sum and the mesh size need positive volumes");
    return s;
}

struct TimeResult {
    double time;
    std::string name;
    std::size_t points;
    std::vector<double> d21, d32, ratio;
    std::vector<OrderEstimate::Order> order;
};

// The grid's points inside the intersection of the runs' bounding boxes, x fastest.
std::vector<SamplePoint> gridPoints(const std::array<RunState, 3>& states, int dim, double spacing,
                                    const KeywordValues& gridValues) {
    std::array<long long, 3> first{0, 0, 0}, count{1, 1, 1};
    double total = 1.0;
    for (int c = 0; c < dim; ++c) {
        double lo = -HUGE_VAL, hi = HUGE_VAL;
        for (const auto& s : states) {
            lo = std::max(lo, s.lo[c]);
            hi = std::min(hi, s.hi[c]);
        }
        // A point on the box's face up to round-off (lo = 3 * 0.1) is in it.
        const double iLo = std::ceil(lo / spacing - 1e-9), iHi = std::floor(hi / spacing + 1e-9);
        if (iHi < iLo) return {};
        first[c] = (long long)iLo;
        count[c] = (long long)(iHi - iLo) + 1;
        total *= double(count[c]);
    }
    if (total > maxGridPoints)
        throw gridValues.error("spacing", "the grid over the runs' common bounding box would have " +
                                              number(total, "%.3g") + " points (at most " +
                                              number(maxGridPoints, "%.3g") + "); give a larger spacing");
    std::vector<SamplePoint> points;
    points.reserve(std::size_t(total));
    for (long long k = 0; k < count[2]; ++k)
        for (long long j = 0; j < count[1]; ++j)
            for (long long i = 0; i < count[0]; ++i)
                points.push_back({double(first[0] + i) * spacing,
                                  dim > 1 ? double(first[1] + j) * spacing : 0.0,
                                  dim > 2 ? double(first[2] + k) * spacing : 0.0});
    return points;
}

// S(x) = sum_j V_j W(|x - x_j|, h_j) over the stencil's particles (all those within reach).
double kernelSum(const RunState& s, const Interpolation::Stencil& stencil, const SamplePoint& x, int dim) {
    const Kernel& kernel = s.interpolation->kernel();
    double sum = 0.0;
    for (std::size_t j : stencil.particles) {
        double r2 = 0.0;
        for (int c = 0; c < dim; ++c) r2 += (s.position[j][c] - x[c]) * (s.position[j][c] - x[c]);
        sum += s.volume[j] * kernel.W(std::sqrt(r2), s.h[j], dim);
    }
    return sum;
}

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const auto& w : words) text += (text.empty() ? "" : " ") + w;
    return text;
}

int run(const Arguments& args) {
    const Case study(args.caseDir());
    const Dictionary dict = study.readSystem(dictName);
    const KeywordValues values = orderEstimateKeywords().read(dict);
    const auto& runNames = values.words("runs");
    if (runNames.size() != 3)
        throw values.error("runs", "expected exactly 3 runs (coarse medium fine), found " +
                                       std::to_string(runNames.size()) + ": (" + joined(runNames) + ")");
    const auto& fields = values.words("fields");
    const OrderEstimate::Norm norm =
        values.word("norm") == "l2" ? OrderEstimate::Norm::l2 : OrderEstimate::Norm::infinity;
    const KeywordValues& gridValues = values.nested("grid");
    const double spacing = gridValues.scalar("spacing");
    const double interior = values.scalar("interior");
    // The kernel is checked here, at its place in the file, and its entries marked read; each
    // run's interpolation makes its own from a copy.
    if (values.given("kernel")) Kernel::New(values.dictionary("kernel"));
    refuseUnknownEntries(dict);

    std::array<Run, 3> runs;
    for (int k = 0; k < 3; ++k) {
        Run& r = runs[k];
        r.name = runNames[std::size_t(k)];
        r.dir = study.root() / r.name;
        std::error_code ec;
        if (!fs::is_directory(r.dir, ec))
            throw values.error("runs", std::string("the ") + runRoles[std::size_t(k)] + " run's directory " +
                                           r.dir.string() + " does not exist");
        for (const auto& t : Case(r.dir).timeDirectories())
            if (fs::exists(timeParticleFile(r.dir / t.name), ec)) r.times.push_back(t);
        if (r.times.empty())
            throw values.error("runs", std::string("the ") + runRoles[std::size_t(k)] + " run " +
                                           r.dir.string() + " has no time directory with a " +
                                           particleFileName + " or " + particleIndexFileName);
    }
    const auto common = commonTimes(runs);
    if (common.empty()) {
        std::string message = "the runs have no time in common:";
        for (const auto& r : runs) {
            message += "\n    " + r.name + ":";
            for (const auto& t : r.times) message += " " + t.name;
        }
        throw values.error("runs", message);
    }
    const auto times = chosenTimes(args, common);

    Log::info("orderEstimate: runs " + joined(runNames) + ", fields " + joined(fields) + ", " +
              OrderEstimate::normName(norm) + " norm, grid spacing " + number(spacing) + ", interior " +
              number(interior) + ", " + values.word("interpolation") + " interpolation; " +
              std::to_string(times.size()) + " of " + std::to_string(common.size()) + " common times");

    std::vector<Column> columns;
    std::vector<TimeResult> results;
    std::vector<std::string> emptyTimes;       // no grid point inside all three bodies
    std::array<std::size_t, 3> firstCounts{};  // N_k and dx_k at the first time compared
    std::array<double, 3> firstSpacing{};
    std::array<std::string, 3> volumeSources;
    std::string firstTimeName;
    std::string countChanges;  // times at which a run's N differs from the first time's
    int dim = 0;

    for (const auto& time : times) {
        std::array<RunState, 3> states;
        for (int k = 0; k < 3; ++k) {
            states[k] = loadRun(runs[k], time.names[k], dict, values, fields, k);
            const fs::path& file = states[k].file;
            if (k == 0) dim = states[0].particles().dimension();
            if (states[k].particles().dimension() != dim)
                throw values.error(
                    "runs", file.string() + " is " + std::to_string(states[k].particles().dimension()) +
                                "D, the coarse run's particles are " + std::to_string(dim) + "D");
            const auto& runColumns = states[k].columns;
            if (columns.empty()) columns = runColumns;
            bool sameColumns = runColumns.size() == columns.size();
            for (std::size_t c = 0; sameColumns && c < columns.size(); ++c)
                sameColumns = runColumns[c].name == columns[c].name;
            if (!sameColumns)
                throw values.error("fields", file.string() +
                                                 ": the fields have other components than in the "
                                                 "coarse run at the first time (a field of another kind?)");
        }
        std::array<double, 3> counts{};
        for (int k = 0; k < 3; ++k) counts[k] = double(states[k].particles().size());
        for (int k = 1; k < 3; ++k)
            if (!(counts[k] > counts[k - 1]))
                throw values.error("runs",
                                   "the runs must be given coarse to fine, with strictly increasing particle "
                                   "counts; at time " +
                                       time.names[0] + " the " + runRoles[std::size_t(k)] + " run '" +
                                       runs[k].name + "' has " + number(counts[k]) + " particles, the " +
                                       runRoles[std::size_t(k - 1)] + " run '" + runs[k - 1].name + "' " +
                                       number(counts[k - 1]) + " (N1 N2 N3 = " + number(counts[0]) + " " +
                                       number(counts[1]) + " " + number(counts[2]) + ")");
        if (firstTimeName.empty()) {
            firstTimeName = time.names[0];
            for (int k = 0; k < 3; ++k) {
                firstCounts[k] = states[k].particles().size();
                firstSpacing[k] = OrderEstimate::meanSpacing(states[k].totalVolume, counts[k], dim);
                volumeSources[k] = states[k].volumeSource;
            }
        } else {
            for (int k = 0; k < 3; ++k)
                if (states[k].particles().size() != firstCounts[k])
                    countChanges += " " + runs[k].name + "@" + time.names[k] + "=" +
                                    std::to_string(states[k].particles().size());
        }
        const OrderEstimate estimate(counts, dim);

        // Each grid point in turn: it counts when every run has it inside and determined; then the
        // fields' values of all three runs there are kept.
        const auto points = gridPoints(states, dim, spacing, gridValues);
        std::array<std::vector<std::vector<double>>, 3> sampled;  // [run][column][kept point]
        for (auto& s : sampled) s.assign(columns.size(), {});
        std::size_t kept = 0, undetermined = 0;
        std::array<Interpolation::Stencil, 3> stencils;
        for (const auto& x : points) {
            bool inside = true, determined = true;
            for (int k = 0; k < 3 && inside && determined; ++k) {
                stencils[k] = states[k].interpolation->stencil(x);
                inside = stencils[k].status != Interpolation::Status::noNeighbours &&
                         kernelSum(states[k], stencils[k], x, dim) >= interior;
                determined = stencils[k].status == Interpolation::Status::ok;
            }
            if (!inside) continue;
            if (!determined) {
                ++undetermined;
                continue;
            }
            ++kept;
            for (int k = 0; k < 3; ++k)
                for (std::size_t c = 0; c < columns.size(); ++c) {
                    const FieldBase& f = *states[k].particles().findField(columns[c].field);
                    double value = 0.0;
                    for (std::size_t q = 0; q < stencils[k].particles.size(); ++q)
                        value += stencils[k].weights[q] *
                                 f.component(stencils[k].particles[q], columns[c].component);
                    sampled[k][c].push_back(value);
                }
        }
        if (undetermined)
            Log::warning(
                "time " + time.names[0] + ": " + std::to_string(undetermined) +
                " grid points inside the bodies left out: the mls fit is undetermined there in some run "
                "(neighbours not spanning the dimension)");
        if (kept == 0) {
            Log::warning("time " + time.names[0] + " skipped: none of the " + std::to_string(points.size()) +
                         " grid points (spacing " + number(spacing) +
                         ") in the runs' common bounding box is inside " +
                         "all three bodies (kernel sum >= interior " + number(interior) + ")");
            emptyTimes.push_back(time.names[0]);
            continue;
        }

        TimeResult result{time.value, time.names[0], kept, {}, {}, {}, {}};
        std::string line = "time " + time.names[0] + ": " + std::to_string(kept) + " grid points;";
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const double d21 = OrderEstimate::differenceNorm(sampled[1][c], sampled[0][c], norm);
            const double d32 = OrderEstimate::differenceNorm(sampled[2][c], sampled[1][c], norm);
            double magnitude = 0.0;
            for (const auto& run : sampled)
                for (double v : run[c]) magnitude = std::max(magnitude, std::abs(v));
            const auto order = estimate.order(d32, d21, magnitude);
            result.d21.push_back(d21);
            result.d32.push_back(d32);
            result.ratio.push_back(d21 > 0.0 ? d32 / d21 : std::numeric_limits<double>::quiet_NaN());
            result.order.push_back(order);
            line += " " + columns[c].name + " " +
                    (order.status == OrderEstimate::Status::ok ? number(order.value, "%.4g")
                                                               : OrderEstimate::statusText(order.status));
        }
        Log::info(line);
        results.push_back(std::move(result));
    }
    if (results.empty())
        throw values.error("interior", "at none of the " + std::to_string(times.size()) +
                                           " times is a grid point (spacing " + number(spacing) +
                                           ") inside all three bodies (kernel sum >= " + number(interior) +
                                           "); give a finer grid spacing or a lower interior");

    // The table, whole, through a temporary file and a rename.
    const fs::path outDir = study.postProcessing() / "orderEstimate";
    fs::create_directories(outDir);
    {
        std::ostringstream csv;
        csv << "time,points";
        for (const auto& c : columns)
            csv << "," << c.name << "_d21," << c.name << "_d32," << c.name << "_ratio," << c.name << "_order";
        csv << "\n";
        for (const auto& r : results) {
            csv << number(r.time) << "," << r.points;
            for (std::size_t c = 0; c < columns.size(); ++c)
                csv << "," << number(r.d21[c]) << "," << number(r.d32[c]) << "," << number(r.ratio[c]) << ","
                    << number(r.order[c].value);
            csv << "\n";
        }
        writeFileAtomically(outDir / "orderEstimate.csv", csv.str());
    }

    // The summary.
    std::ostringstream s;
    s << "Order estimate (von Nida 2005, Lemma 7.1) of "
      << fs::absolute(study.root()).lexically_normal().string() << "\n";
    s << "runs          " << joined(runNames) << "\n";
    s << "particles     N1 N2 N3 = " << firstCounts[0] << " " << firstCounts[1] << " " << firstCounts[2]
      << " (" << dim << "D, at time " << firstTimeName << ")\n";
    s << "mesh size     dx1 dx2 dx3 = " << number(firstSpacing[0], "%.6g") << " "
      << number(firstSpacing[1], "%.6g") << " " << number(firstSpacing[2], "%.6g")
      << "   dx = (sum V / N)^(1/d)\n";
    for (int k = 0; k < 3; ++k)
        if (volumeSources[k] != "mass/density")
            s << "  note: the volumes of run '" << runs[k].name << "' are " << volumeSources[k] << "\n";
    if (!countChanges.empty())
        s << "  note: particle counts change over time (run@time=N):" << countChanges
          << "; each time's order uses its own counts\n";
    s << "norm          " << OrderEstimate::normName(norm) << "; grid spacing " << number(spacing)
      << ", interior " << number(interior) << ", " << values.word("interpolation") << " interpolation\n";
    s << "times         " << results.size() << " compared (" << results.front().name << " to "
      << results.back().name << ")";
    if (!emptyTimes.empty()) s << "; " << emptyTimes.size() << " skipped, no grid point inside all bodies:";
    for (const auto& t : emptyTimes) s << " " << t;
    s << "\n\n";
    char head[160];
    std::snprintf(head, sizeof head, "%-24s %12s %10s %10s %10s\n", "field", "mean order", "times", "min",
                  "max");
    s << head;
    std::vector<std::string> notes;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        double sum = 0.0, lo = HUGE_VAL, hi = -HUGE_VAL;
        std::size_t used = 0;
        std::map<OrderEstimate::Status, std::size_t> leftOut;
        for (const auto& r : results) {
            const auto& o = r.order[c];
            if (o.status != OrderEstimate::Status::ok) {
                ++leftOut[o.status];
                continue;
            }
            sum += o.value;
            lo = std::min(lo, o.value);
            hi = std::max(hi, o.value);
            ++used;
        }
        char row[200];
        const std::string usedText = std::to_string(used) + "/" + std::to_string(results.size());
        if (used)
            std::snprintf(row, sizeof row, "%-24s %12.4f %10s %10.4f %10.4f\n", columns[c].name.c_str(),
                          sum / double(used), usedText.c_str(), lo, hi);
        else
            std::snprintf(row, sizeof row, "%-24s %12s %10s %10s %10s\n", columns[c].name.c_str(), "none",
                          usedText.c_str(), "-", "-");
        s << row;
        for (const auto& [status, n] : leftOut) {
            std::string why =
                status == OrderEstimate::Status::belowRange
                    ? "the order is below " + number(OrderEstimate::lowestOrder) +
                          " (the differences do not shrink: not converging, or not yet asymptotic)"
                : status == OrderEstimate::Status::aboveRange
                    ? "the order is above " + number(OrderEstimate::highestOrder) +
                          " (||phi3 - phi2|| vanishes against ||phi2 - phi1||)"
                    : "no ratio (||phi2 - phi1|| is zero, below " + number(OrderEstimate::roundOffLevel) +
                          " of the values (round-off), or a value is not finite)";
            notes.push_back(columns[c].name + ": " + std::to_string(n) + " time" + (n == 1 ? "" : "s") +
                            " left out of the mean: " + why);
        }
    }
    for (const auto& n : notes) s << "  " << n << "\n";
    s << "\nper time: " << (outDir / "orderEstimate.csv").string() << "\n";
    writeFileAtomically(outDir / "summary.txt", s.str());
    Log::info("\n" + s.str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const ApplicationInfo info{
        "orderEstimate",
        "Observed order of convergence of particle fields from three runs at increasing particle counts "
        "(von Nida 2005, Lemma 7.1), compared on a regular grid (system/orderEstimateDict).",
        {{"time", "t|a:b",
          "the time, or range of times, to compare (default: all that the three runs share)"},
         {"latestTime", "", "compare the latest common time only"}},
        {}};
    return runApplication(argc, argv, info, run);
}
