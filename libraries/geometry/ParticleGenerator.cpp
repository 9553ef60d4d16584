#include "geometry/ParticleGenerator.hpp"

#include "core/Log.hpp"
#include "geometry/Lattice.hpp"
#include "geometry/Shape.hpp"
#include "particles/ParticleSet.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <sys/resource.h>
#include <unistd.h>

namespace mfdyn {

namespace {

std::string formatNumber(double x) {
    if (x == std::numeric_limits<double>::infinity()) return "more than 1e308";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

// The scalar and vector fields that a model of the toolkit reads from 0/particles.vtp as its
// initial state, where a uniform value per region makes sense. Any other name is refused unless
// `userFields` lists it: a misspelt `velocty` would otherwise be written as a field no model
// reads and leave the block at rest without a word.
struct KnownField {
    const char* name;
    bool vector;
    const char* meaning;
};
constexpr KnownField knownFields[] = {
    {"velocity", true, "m/s; every solver"},
    {"pressure", false, "Pa; impactSph sets the internal energy from it through the equation of state"},
    {"specificInternalEnergy", false, "J/kg; impactSph, instead of pressure"},
    {"temperature", false, "K; impactSph's thermal strength laws (default: the law's initial temperature)"},
    {"smoothingLength", false, "m; impactSph (default: from the smoothingLength law)"},
    {"plasticStrain", false, "-; the initial equivalent plastic strain of plastic strength laws"},
};
// Set by particleGen itself from the region's entries; a `fields` entry would contradict them
// (a `density` there would disagree with the mass = density x volume already computed).
constexpr const char* generatedFields[] = {"position", "globalId", "region", "mass", "material", "density"};
// Fixed names (doc/architecture.md "Field names") that the solvers compute at start or every
// step, so an initial value would be overwritten or is not a scalar or vector.
constexpr const char* computedFields[] = {"acceleration",     "referencePosition", "deformationGradient",
                                          "cofactor",         "jacobian",          "firstPiolaStress",
                                          "deviatoricStress", "soundSpeed"};

bool contains(const auto& list, const std::string& name) {
    for (const auto& n : list)
        if (name == n) return true;
    return false;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The closest known or user field to a name no model reads: by edit distance, else the one name
// that contains it ignoring case (`internalEnergy` -> `specificInternalEnergy`), for names of 4
// letters or more (a short one is contained in too many).
std::string suggestField(const std::string& name, const std::vector<std::string>& candidates) {
    std::string guess = closestMatch(name, candidates);
    if (!guess.empty() || name.size() < 4) return guess;
    for (const auto& c : candidates)
        if (lower(c).find(lower(name)) != std::string::npos ||
            lower(name).find(lower(c)) != std::string::npos)
            return c;
    return "";
}

// Memory that generation may use: MemAvailable of /proc/meminfo (what the kernel can give
// without swapping), lowered to the room left under a cgroup v2 limit (a container or a batch
// job's allocation) or under an address-space limit, when there is one.
struct MemoryBudget {
    double bytes = 0;
    std::string source;
};

MemoryBudget availableMemory() {
    MemoryBudget budget{std::numeric_limits<double>::infinity(), ""};
    {
        std::ifstream in("/proc/meminfo");
        std::string key;
        double value;
        std::string unit;
        while (in >> key >> value) {
            std::getline(in, unit);
            if (key == "MemAvailable:") {
                budget = {value * 1024, "MemAvailable in /proc/meminfo"};
                break;
            }
        }
    }
    std::ifstream maxFile("/sys/fs/cgroup/memory.max"), currentFile("/sys/fs/cgroup/memory.current");
    double limit = 0, current = 0;
    if (maxFile >> limit && currentFile >> current && limit - current < budget.bytes)
        budget = {std::max(0.0, limit - current), "the cgroup limit /sys/fs/cgroup/memory.max"};
    // `ulimit -v` (a batch system's address-space limit), less the address space in use.
    rlimit as{};
    std::ifstream statm("/proc/self/statm");
    double pages = 0;
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY && statm >> pages) {
        const double room = double(as.rlim_cur) - pages * double(sysconf(_SC_PAGESIZE));
        if (room < budget.bytes) budget = {std::max(0.0, room), "the address-space limit (ulimit -v)"};
    }
    return budget;
}

// Peak memory of particleGen per particle written, measured as /usr/bin/time's maximum resident
// size: 128 bytes for a 3D cubic block of 4.0e6 particles with velocity and pressure (508 MB, less
// the 6 MB of a one-particle run). That is the generator's 40-byte record per particle and the
// particle set (position, globalId, region, mass, density, velocity, pressure: 88 bytes in 3D).
// 200 leaves room for more initial fields (8 bytes per scalar, 24 per vector) and `material`.
constexpr double bytesPerParticle = 200;
// The lattice's points over a region's bounding box, while that region is generated: dim
// coordinates and one volume each.
double bytesPerSite(int dim) {
    return 8.0 * (dim + 1);
}

// A particle volume or mass has to be a normal positive double: zero (underflow) gives
// particles of no mass, inf or NaN poisons every sum, and a subnormal one has lost precision and,
// below 5.6e-309, an infinite reciprocal (a solver divides by m and by V = m/rho).
bool normalPositive(double x) {
    return x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max();
}

// The material names of constant/materialProperties (`materials { name { ... } ... }`), when the
// case has that file; particleGenDict is read from <case>/system/.
struct MaterialTable {
    bool found = false;
    std::string file;
    std::set<std::string> names;
};

MaterialTable readMaterials(const Dictionary& particleGenDict) {
    MaterialTable table;
    const auto& where = particleGenDict.where();
    if (!where.file) return table;
    const std::filesystem::path dictFile = *where.file;
    const auto file = dictFile.parent_path().parent_path() / "constant" / "materialProperties";
    if (!std::filesystem::exists(file)) return table;
    const Dictionary props = Dictionary::read(file);
    table.found = true;
    table.file = file.string();
    if (const Dictionary* m = props.findDict("materials"))
        for (const auto& e : m->entries())
            if (e->isDict()) table.names.insert(e->key);
    return table;
}

// angularVelocity { omega (0 0 10); centre (0 0 0); }: ω in rad/s, a vector in 3D; in 2D the
// rotation is about z, given as a scalar or as (0 0 ω).
void readAngularVelocity(const Dictionary& spin, int dim, std::optional<std::array<double, 3>>& omega,
                         std::array<double, 3>& centre) {
    if (dim == 1) throw spin.error("omega", "a 1D case cannot rotate");
    std::array<double, 3> w{0, 0, 0};
    const Entry& e = spin.entry("omega");
    if (dim == 2 && e.tokens.size() == 1 && e.tokens[0].isNumber()) {
        w[2] = spin.get<double>("omega");
    } else {
        const auto v = spin.get<std::vector<double>>("omega");
        if (v.size() != 3) throw spin.error("omega", "expected (wx wy wz) in rad/s");
        if (dim == 2 && (v[0] != 0 || v[1] != 0))
            throw spin.error("omega", "a 2D case rotates about z only: expected (0 0 wz) or a scalar");
        w = {v[0], v[1], v[2]};
    }
    for (double x : w)
        if (!std::isfinite(x)) throw spin.error("omega", "omega must be finite, found " + formatNumber(x));
    const auto c = spin.getOrDefault<std::vector<double>>("centre", std::vector<double>(dim, 0.0));
    if (int(c.size()) < dim)
        throw spin.error("centre", "expected a point of " + std::to_string(dim) + " components");
    for (int k = 0; k < dim; ++k) {
        if (!std::isfinite(c[k]))
            throw spin.error("centre", "centre must be finite, found " + formatNumber(c[k]));
        centre[k] = c[k];
    }
    omega = w;
}

}  // namespace

ParticleGenerator::ParticleGenerator(const Dictionary& dict)
    : dict_(dict), dimension_(dict.get<int>("dimension")) {
    if (dimension_ < 1 || dimension_ > 3) throw dict.error("dimension", "dimension must be 1, 2 or 3");
}

std::string ParticleGenerator::knownFieldsHelp() {
    std::string s;
    for (const auto& f : knownFields) {
        const std::string name = f.name;
        s += "  " + name + std::string(name.size() < 24 ? 24 - name.size() : 1, ' ') +
             (f.vector ? "vector, " : "scalar, ") + f.meaning + "\n";
    }
    return s;
}

std::unique_ptr<ParticleSetBase> ParticleGenerator::generate() {
    // Whatever the estimate, an allocation can still fail (memory taken by other processes since);
    // say so in the user's terms instead of "Error (internal): std::bad_alloc".
    try {
        return build();
    } catch (const std::bad_alloc&) {
        throw Error("out of memory while generating particles" +
                    (current_.empty() ? std::string() : " in region '" + current_ + "'") +
                    ": give the regions larger spacings, or run where more memory is free");
    } catch (const std::length_error& e) {
        throw Error("too many particles" +
                    (current_.empty() ? std::string() : " in region '" + current_ + "'") + " (" + e.what() +
                    "): give the regions larger spacings");
    }
}

std::unique_ptr<ParticleSetBase> ParticleGenerator::build() {
    const int dim = dimension_;
    const Dictionary& regions = dict_.subDict("regions");
    if (regions.size() == 0) throw regions.error("", "no regions defined");

    // Field names a model reads: the toolkit's, and `userFields` for a user library's own.
    std::vector<std::string> allowedFields;
    for (const auto& f : knownFields) allowedFields.emplace_back(f.name);
    if (dict_.found("userFields")) {
        for (const auto& name : dict_.get<std::vector<std::string>>("userFields")) {
            if (contains(generatedFields, name))
                throw dict_.error("userFields", "'" + name + "' is set by particleGen itself");
            allowedFields.push_back(name);
        }
    }
    std::string knownList;
    for (const auto& name : allowedFields) knownList += (knownList.empty() ? "" : " ") + name;

    std::vector<std::string> fieldNames;  // union over regions, in order of first appearance
    std::vector<int> fieldComponents;     // 0 for a scalar field, dim for a vector field
    // Per region: what its particles share, so that the per-particle record stays small.
    struct RegionData {
        std::vector<std::pair<int, std::vector<double>>> values;  // field index, components
        std::int64_t material = -1;
        double density = 0;
        std::optional<std::array<double, 3>> omega;
        std::array<double, 3> omegaCentre{0, 0, 0};
        std::size_t velocityValue = 0;  // the entry of `values` that the rotation adds to
    };
    struct Particle {
        std::array<double, 3> x;
        std::uint32_t region;
        double mass;
    };
    std::vector<Particle> all;
    std::vector<RegionData> data;
    std::vector<std::string> regionNames;
    std::vector<std::set<std::string>> takenBy;  // per region: the later regions that took particles
    report_.clear();
    current_.clear();
    const MemoryBudget memory = availableMemory();

    // Equal-mass regions share the particle mass of the lightest one (lowest density × its own
    // lattice's volume per point); the others are set to it by coarsening or refining their
    // spacing (doc/methods/sph-impact.md §4, scheme (a)).
    double equalMass = 0, lowestDensity = 0;
    std::vector<bool> isEqualMass;
    for (const auto& entry : regions.entries()) {
        if (!entry->isDict()) throw regions.error(entry->key, "expected a region dictionary");
        const Dictionary& r = regions.subDict(entry->key);
        const auto mode = r.getOrDefault<std::string>("mass", "uniformSpacing");
        if (mode != "uniformSpacing" && mode != "equalMass")
            throw r.error("mass",
                          "expected 'uniformSpacing' (the default: the lattice as given, mass = density × "
                          "volume per point) or 'equalMass', found '" +
                              mode + "'");
        isEqualMass.push_back(mode == "equalMass");
        if (mode != "equalMass") continue;
        const double density = r.get<double>("density");
        if (!(density > 0) || !std::isfinite(density))
            throw r.error("density", "density must be positive and finite, found " + formatNumber(density));
        const auto lattice = Lattice::New(r.subDict("lattice"), dim);
        if (!(lattice->spacing() > 0))
            throw r.subDict("lattice").error("points",
                                             "`mass equalMass` scales the lattice's spacing: give "
                                             "`spacing` instead of `points`");
        const double volume = lattice->pointVolume();
        const double m = density * volume;
        if (!normalPositive(volume) || !normalPositive(m))
            throw r.error("lattice", "region '" + entry->key +
                                         "': the particle mass density x volume = " + formatNumber(density) +
                                         " x " + formatNumber(volume) + " = " + formatNumber(m) +
                                         " is not a positive normal number (underflow or overflow): give the "
                                         "spacing in metres and the density in kg/m^3");
        if (equalMass == 0 || density < lowestDensity) {
            equalMass = m;
            lowestDensity = density;
        }
    }

    const MaterialTable materials = readMaterials(dict_);
    std::vector<std::string> materialNames;
    bool anyMaterial = false, anyWithout = false;

    for (const auto& entry : regions.entries()) {
        const Dictionary& r = regions.subDict(entry->key);
        current_ = entry->key;
        const auto shape = Shape::New(r.subDict("shape"), dim);
        auto lattice = Lattice::New(r.subDict("lattice"), dim);
        RegionData region;
        region.density = r.get<double>("density");
        if (!(region.density > 0) || !std::isfinite(region.density))
            throw r.error("density",
                          "density must be positive and finite, found " + formatNumber(region.density));
        const double density = region.density;
        const bool takeOver = r.getOrDefault<bool>("override", true);
        if (isEqualMass[regionNames.size()]) {
            // Volume per point scales as spacing^dim on every lattice: s' = s (m*/(ρ V(s)))^(1/dim).
            const double scale = std::pow(equalMass / (density * lattice->pointVolume()), 1.0 / dim);
            const double scaledSpacing = lattice->spacing() * scale;
            if (!(scaledSpacing > 0) || !std::isfinite(scaledSpacing))
                throw r.error("lattice", "region '" + entry->key + "': the equal-mass spacing " +
                                             formatNumber(lattice->spacing()) + " x " + formatNumber(scale) +
                                             " is not a positive finite length");
            Dictionary scaled = r.subDict("lattice");
            char spacing[40];
            std::snprintf(spacing, sizeof spacing, "%.17g", scaledSpacing);
            scaled.set("spacing", spacing);
            lattice = Lattice::New(scaled, dim);
        }

        if (const auto name = r.getOptional<std::string>("material")) {
            anyMaterial = true;
            if (materials.found && !materials.names.contains(*name)) {
                std::string valid;
                for (const auto& n : materials.names) valid += " " + n;
                throw r.error("material", "unknown material '" + *name + "' (not in " + materials.file +
                                              "); valid materials:" + (valid.empty() ? " none" : valid));
            }
            const auto it = std::find(materialNames.begin(), materialNames.end(), *name);
            region.material = std::int64_t(it - materialNames.begin());
            if (it == materialNames.end()) materialNames.push_back(*name);
        } else {
            anyWithout = true;
        }
        if (anyMaterial && anyWithout)
            throw r.error("material",
                          "region '" + entry->key + "': either every region names its material or none does");

        // `fields velocity;` (not a dictionary) was skipped without a word.
        for (const char* key : {"fields", "angularVelocity"})
            if (r.found(key) && !r.isDict(key))
                throw r.error(key, std::string("expected a dictionary: ") + key + " { ... }");
        if (const Dictionary* spin = r.findDict("angularVelocity"))
            readAngularVelocity(*spin, dim, region.omega, region.omegaCentre);

        auto& values = region.values;
        if (const Dictionary* fields = r.findDict("fields")) {
            for (const auto& f : fields->entries()) {
                const std::string& name = f->key;
                if (contains(generatedFields, name))
                    throw fields->error(name,
                                        "'" + name + "' is set by particleGen itself" +
                                            (name == "density" ? " from the region's `density` entry" : ""));
                if (!contains(allowedFields, name)) {
                    const std::string guess = suggestField(name, allowedFields);
                    throw fields->error(
                        name,
                        "unknown field '" + name + "'" +
                            (guess.empty() ? std::string() : " (did you mean '" + guess + "'?)") +
                            (contains(computedFields, name) ? "; the solvers compute it themselves" : "") +
                            "; known fields: " + knownList +
                            "; a field that a model of your own reads is declared with `userFields (" + name +
                            ");` at the top of particleGenDict");
                }
                std::vector<double> v;
                // A bare number is a scalar, a parenthesised list a vector (also in 1D, where both have
                // one component): recorded as 0 or dim in fieldComponents.
                const bool scalar = f->tokens.size() == 1 && f->tokens[0].isNumber();
                for (const auto& k : knownFields)
                    if (name == k.name && scalar == k.vector)
                        throw fields->error(name,
                                            "'" + name + "' is a " + (k.vector ? "vector" : "scalar") +
                                                " field: expected " +
                                                (k.vector ? "a list of " + std::to_string(dim) + " components"
                                                          : std::string("a number")));
                const int components = scalar ? 0 : dim;
                if (scalar) {
                    v = {fields->get<double>(name)};
                } else {
                    v = fields->get<std::vector<double>>(name);
                    if (int(v.size()) < dim)
                        throw fields->error(
                            name, "expected a scalar or a vector of " + std::to_string(dim) + " components");
                    for (std::size_t k = dim; k < v.size(); ++k)
                        if (v[k] != 0)
                            throw fields->error(name, "component " + std::to_string(k + 1) +
                                                          " is non-zero in a " + std::to_string(dim) +
                                                          "D case");
                    v.resize(dim);
                }
                // 1e400 reads as inf; a solver would start from it and write NaN from the first step.
                for (std::size_t k = 0; k < v.size(); ++k)
                    if (!std::isfinite(v[k]))
                        throw fields->error(name, "region '" + entry->key + "': field '" + name + "'" +
                                                      (scalar ? "" : " component " + std::to_string(k + 1)) +
                                                      " is " + formatNumber(v[k]) +
                                                      ": initial values must be finite");
                // Every solver forms v·v (kinetic energy, time-step limits): its square must be finite too.
                double square = 0;
                for (double x : v) square += x * x;
                if (!scalar && !std::isfinite(square))
                    throw fields->error(name, "region '" + entry->key + "': field '" + name +
                                                  "' is so large that its square overflows: components must "
                                                  "be within about +-1e150");
                int index = -1;
                for (std::size_t k = 0; k < fieldNames.size(); ++k)
                    if (fieldNames[k] == name) index = int(k);
                if (index < 0) {
                    index = int(fieldNames.size());
                    fieldNames.push_back(name);
                    fieldComponents.push_back(components);
                } else if (fieldComponents[index] != components) {
                    throw fields->error(
                        name, "field '" + name + "' is a scalar in one region and a vector in another");
                }
                values.emplace_back(index, v);
            }
        }
        // Rigid rotation adds ω × (x − c) to the velocity, which becomes a field if not one yet.
        region.velocityValue = values.size();
        if (region.omega) {
            int index = -1;
            for (std::size_t k = 0; k < fieldNames.size(); ++k)
                if (fieldNames[k] == "velocity") index = int(k);
            if (index < 0) {
                index = int(fieldNames.size());
                fieldNames.push_back("velocity");
                fieldComponents.push_back(dim);
            } else if (fieldComponents[index] != dim) {
                throw r.error("angularVelocity", "'velocity' is a scalar field elsewhere");
            }
            for (std::size_t k = 0; k < values.size(); ++k)
                if (values[k].first == index) region.velocityValue = k;
            if (region.velocityValue == values.size())
                values.emplace_back(index, std::vector<double>(dim, 0.0));
        }

        const std::uint32_t regionId = std::uint32_t(regionNames.size());
        regionNames.push_back(entry->key);
        takenBy.emplace_back();
        if (takeOver) {
            std::erase_if(all, [&](const Particle& p) {
                if (!shape->inside(p.x.data())) return false;
                takenBy[p.region].insert(entry->key);
                return true;
            });
        }

        // Count before allocating: the lattice's points over the shape's bounding box, and the
        // share of them inside the shape (its exact volume over the box's, when known), against the
        // memory that is free. A spacing far too small otherwise ends in std::bad_alloc, or, when the
        // count overflows, in a single particle.
        const BoundingBox box = shape->bounds();
        const double sites = lattice->pointCount(box);
        double boxVolume = 1;
        for (int d = 0; d < dim; ++d) boxVolume *= box.max[d] - box.min[d];
        const auto exact = shape->volume();
        const double inside = exact && boxVolume > 0 ? sites * std::min(1.0, *exact / boxVolume) : sites;
        const double need = (double(all.size()) + inside) * bytesPerParticle + sites * bytesPerSite(dim);
        if (!(need <= memory.bytes)) {
            std::string extent;
            for (int d = 0; d < dim; ++d) extent += (d ? " x " : "") + formatNumber(box.max[d] - box.min[d]);
            throw r.error(
                "lattice",
                "region '" + entry->key + "' would hold about " + formatNumber(inside) + " particles (" +
                    r.subDict("lattice").getOrDefault<std::string>("type", "?") + " lattice of spacing " +
                    formatNumber(lattice->spacing()) + " m: " + formatNumber(sites) +
                    " points over the shape's bounding box of " + extent + " m" +
                    (all.empty()
                         ? ""
                         : ", after " + std::to_string(all.size()) + " particles of earlier regions") +
                    "); at " + formatNumber(bytesPerParticle) + " bytes per particle that needs " +
                    formatBytes(need) + ", and " +
                    (memory.source.empty()
                         ? std::string("no memory figure is known")
                         : formatBytes(memory.bytes) + " is available (" + memory.source + ")") +
                    ": give a larger spacing");
        }

        const auto points = lattice->points(box);
        // Per point: the same for most lattices, smaller on the faces of a nodal one.
        const auto volumes = lattice->pointVolumes(box, points);
        RegionReport rep{entry->key, 0, 0, exact.value_or(-1), 0, lattice->spacing()};
        all.reserve(all.size() + std::size_t(std::ceil(inside)));
        for (std::size_t p = 0; p * dim < points.size(); ++p) {
            std::array<double, 3> x{0, 0, 0};
            for (int c = 0; c < dim; ++c) x[c] = points[p * dim + c];
            if (!shape->inside(x.data())) continue;
            const double mass = density * volumes[p];
            if (!normalPositive(volumes[p]) || !normalPositive(mass))
                throw r.error("lattice",
                              "region '" + entry->key + "': the particle mass density x volume = " +
                                  formatNumber(density) + " x " + formatNumber(volumes[p]) + " = " +
                                  formatNumber(mass) + " (spacing " + formatNumber(lattice->spacing()) +
                                  " m) is not a positive normal number (underflow or overflow): give "
                                  "the spacing in metres and the density in kg/m^3");
            all.push_back({x, regionId, mass});
            ++rep.count;
            rep.volume += volumes[p];
            rep.mass += mass;
        }
        if (rep.count == 0)
            throw r.error("shape", "region '" + entry->key + "' is empty: no lattice point of spacing " +
                                       formatNumber(lattice->spacing()) + " m falls inside its shape");
        // Material points (materialPoints lattice): V_p = the shape's exact volume / N, the
        // material point method's rule (doc/methods/mpm.md section 3), so that the body's mass is
        // density x its exact volume; without a closed-form volume the lattice's volumes stay.
        if (lattice->volumeFromShape()) {
            if (exact) {
                const double share = *exact / double(rep.count), mass = density * share;
                if (!normalPositive(share) || !normalPositive(mass))
                    throw r.error("lattice", "region '" + entry->key +
                                                 "': the particle mass density x volume = " +
                                                 formatNumber(density) + " x " + formatNumber(share) +
                                                 " is not a positive normal number (underflow or overflow)");
                for (std::size_t p = all.size() - rep.count; p < all.size(); ++p) all[p].mass = mass;
                rep.volume = *exact;
                rep.mass = mass * double(rep.count);
            } else {
                Log::info(r.where().str() + ": region '" + entry->key + "': its " +
                          r.subDict("shape").getOrDefault<std::string>("type", "?") +
                          " shape has no closed-form volume, so its material points keep the lattice volume "
                          "(sub-cell volume / points per sub-cell): " +
                          formatNumber(rep.volume) + " in all");
            }
        }
        report_.push_back(rep);
        data.push_back(std::move(region));
    }
    current_.clear();

    // Counts after later regions took particles over.
    for (auto& rep : report_) rep.count = 0, rep.mass = 0, rep.volume = 0;
    for (const auto& p : all) {
        auto& rep = report_[p.region];
        ++rep.count;
        rep.mass += p.mass;
    }
    for (std::size_t k = 0; k < report_.size(); ++k) {
        // A region left without particles would still be named in the particle file; per-region sums
        // (its mass, its centre) would divide by zero in the solvers.
        if (report_[k].count == 0) {
            std::string takers;
            for (const auto& t : takenBy[k]) takers += (takers.empty() ? "'" : ", '") + t + "'";
            throw regions.error(report_[k].name,
                                "region '" + report_[k].name + "' has no particles left: the later region" +
                                    (takenBy[k].size() > 1 ? "s " : " ") + takers +
                                    " took them all (override yes, the default); give " +
                                    (takenBy[k].size() > 1 ? "them" : "it") +
                                    " `override no;` or remove region '" + report_[k].name + "'");
        }
        report_[k].volume = report_[k].mass / data[k].density;
        // A lattice too coarse for its shape (a 1 mm plate at 1 cm spacing) still gives particles,
        // but their mass is not the shape's: say so, unless later regions took some of them.
        const double exact = report_[k].exactVolume;
        if (exact > 0 && takenBy[k].empty() && std::abs(report_[k].volume - exact) > 0.25 * exact)
            Log::warning(regions.findEntry(report_[k].name)->where.str() + ": region '" + report_[k].name +
                         "': its particles stand for a volume of " + formatNumber(report_[k].volume) +
                         " but its shape's is " + formatNumber(exact) + " (" +
                         formatNumber(100 * (report_[k].volume - exact) / exact) + "%): the spacing " +
                         formatNumber(report_[k].spacing) + " m is coarse for this shape");
    }

    // The rotation's velocity ω × (x − c) overflows for an absurd ω or centre: refuse before writing.
    const auto spinVelocity = [&](const Particle& p, double out[3]) {
        const RegionData& rd = data[p.region];
        const auto& w = *rd.omega;
        double r3[3] = {0, 0, 0};
        for (int c = 0; c < dim; ++c) r3[c] = p.x[c] - rd.omegaCentre[c];
        out[0] = w[1] * r3[2] - w[2] * r3[1];
        out[1] = w[2] * r3[0] - w[0] * r3[2];
        out[2] = w[0] * r3[1] - w[1] * r3[0];
    };
    for (const auto& p : all) {
        const RegionData& rd = data[p.region];
        if (!rd.omega) continue;
        double spin[3];
        spinVelocity(p, spin);
        const auto& base = rd.values[rd.velocityValue].second;
        double square = 0;
        for (int c = 0; c < dim; ++c) square += (base[c] + spin[c]) * (base[c] + spin[c]);
        if (!std::isfinite(square))
            throw regions.subDict(regionNames[p.region])
                .error("angularVelocity",
                       "region '" + regionNames[p.region] +
                           "': the rotation's velocity at the particle at distance " +
                           formatNumber(std::hypot(p.x[0] - rd.omegaCentre[0], p.x[1] - rd.omegaCentre[1],
                                                   p.x[2] - rd.omegaCentre[2])) +
                           " m from the centre overflows (its square is not finite)");
    }

    return withDimension(dim, [&](auto d) -> std::unique_ptr<ParticleSetBase> {
        constexpr int Dim = decltype(d)::value;
        auto set = std::make_unique<ParticleSet<Dim>>(all.size());
        set->regionNames = regionNames;
        if (anyMaterial) {
            set->materialNames = materialNames;
            auto& material = set->integerField("material");
            for (std::size_t i = 0; i < all.size(); ++i) material[i] = data[all[i].region].material;
        }
        auto& x = set->position();
        auto& id = set->globalId();
        auto& region = set->region();
        auto& mass = set->scalarField("mass");
        // The initial density is part of the state every method starts from (SPH evolves it;
        // the particle volume is m/rho).
        auto& density = set->scalarField("density");
        for (std::size_t i = 0; i < all.size(); ++i) {
            density[i] = data[all[i].region].density;
            for (int c = 0; c < Dim; ++c) x[i][c] = all[i].x[c];
            id[i] = std::int64_t(i);
            region[i] = all[i].region;
            mass[i] = all[i].mass;
        }
        for (std::size_t f = 0; f < fieldNames.size(); ++f) {
            if (fieldComponents[f] == 0) {
                auto& field = set->scalarField(fieldNames[f]);
                for (std::size_t i = 0; i < all.size(); ++i)
                    for (const auto& [index, v] : data[all[i].region].values)
                        if (index == int(f)) field[i] = v[0];
            } else {
                auto& field = set->vectorField(fieldNames[f]);
                for (std::size_t i = 0; i < all.size(); ++i) {
                    const RegionData& rd = data[all[i].region];
                    for (std::size_t k = 0; k < rd.values.size(); ++k) {
                        if (rd.values[k].first != int(f)) continue;
                        const auto& v = rd.values[k].second;
                        for (int c = 0; c < Dim; ++c) field[i][c] = v[c];
                        if (rd.omega && k == rd.velocityValue) {
                            double spin[3];
                            spinVelocity(all[i], spin);
                            for (int c = 0; c < Dim; ++c) field[i][c] += spin[c];
                        }
                    }
                }
            }
        }
        return set;
    });
}

std::string ParticleGenerator::reportTable() const {
    std::ostringstream s;
    char line[200];
    std::snprintf(line, sizeof line, "%-20s %10s %14s %14s %14s %10s\n", "region", "particles", "volume",
                  "exact volume", "mass", "spacing");
    s << line;
    std::size_t total = 0;
    double mass = 0;
    for (const auto& r : report_) {
        char exact[32] = "-";
        if (r.exactVolume >= 0) std::snprintf(exact, sizeof exact, "%.6g", r.exactVolume);
        std::snprintf(line, sizeof line, "%-20s %10zu %14.6g %14s %14.6g %10.4g\n", r.name.c_str(), r.count,
                      r.volume, exact, r.mass, r.spacing);
        s << line;
        total += r.count;
        mass += r.mass;
    }
    std::snprintf(line, sizeof line, "%-20s %10zu %14s %14s %14.6g\n", "total", total, "", "", mass);
    s << line;
    return s.str();
}

}  // namespace mfdyn
