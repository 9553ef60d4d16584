#include "geometry/ParticleGenerator.hpp"

#include "geometry/Lattice.hpp"
#include "geometry/Shape.hpp"
#include "particles/ParticleSet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

namespace mfdyn {

namespace {

struct Generated {
    std::vector<double> x;  // dim per particle
    std::vector<std::int64_t> region;
    std::vector<double> mass;
    std::vector<std::vector<double>> values;  // per particle, per initial field: its components
};

struct InitialField {
    std::string name;
    std::vector<double> value;  // 1 component (scalar) or dim (vector)
};

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
    const auto c = spin.getOrDefault<std::vector<double>>("centre", std::vector<double>(dim, 0.0));
    if (int(c.size()) < dim)
        throw spin.error("centre", "expected a point of " + std::to_string(dim) + " components");
    for (int k = 0; k < dim; ++k) centre[k] = c[k];
    omega = w;
}

}  // namespace

ParticleGenerator::ParticleGenerator(const Dictionary& dict)
    : dict_(dict), dimension_(dict.get<int>("dimension")) {
    if (dimension_ < 1 || dimension_ > 3) throw dict.error("dimension", "dimension must be 1, 2 or 3");
}

std::unique_ptr<ParticleSetBase> ParticleGenerator::generate() {
    const int dim = dimension_;
    const Dictionary& regions = dict_.subDict("regions");
    if (regions.size() == 0) throw regions.error("", "no regions defined");

    std::vector<std::string> fieldNames;  // union over regions, in order of first appearance
    std::vector<int> fieldComponents;     // 0 for a scalar field, dim for a vector field
    struct Particle {
        std::vector<double> x;
        std::int64_t region;
        double mass;
        std::vector<std::pair<int, std::vector<double>>> values;
        std::int64_t material;
        double density;
    };
    std::vector<Particle> all;
    std::vector<std::string> regionNames;
    report_.clear();

    // Equal-mass regions share the particle mass of the lightest one (lowest density × its own
    // lattice's volume per point); the others are set to it by coarsening or refining their
    // spacing (sph-impact.md §4, scheme (a)).
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
        const double m = density * Lattice::New(r.subDict("lattice"), dim)->pointVolume();
        if (!(density > 0)) throw r.error("density", "density must be positive");
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
        const auto shape = Shape::New(r.subDict("shape"), dim);
        auto lattice = Lattice::New(r.subDict("lattice"), dim);
        const double density = r.get<double>("density");
        if (!(density > 0)) throw r.error("density", "density must be positive");
        const bool takeOver = r.getOrDefault<bool>("override", true);
        if (isEqualMass[regionNames.size()]) {
            // Volume per point scales as spacing^dim on every lattice: s' = s (m*/(ρ V(s)))^(1/dim).
            const double scale = std::pow(equalMass / (density * lattice->pointVolume()), 1.0 / dim);
            Dictionary scaled = r.subDict("lattice");
            char spacing[40];
            std::snprintf(spacing, sizeof spacing, "%.17g", lattice->spacing() * scale);
            scaled.set("spacing", spacing);
            lattice = Lattice::New(scaled, dim);
        }

        std::int64_t materialId = -1;
        if (const auto name = r.getOptional<std::string>("material")) {
            anyMaterial = true;
            if (materials.found && !materials.names.contains(*name)) {
                std::string valid;
                for (const auto& n : materials.names) valid += " " + n;
                throw r.error("material", "unknown material '" + *name + "' (not in " + materials.file +
                                              "); valid materials:" + (valid.empty() ? " none" : valid));
            }
            const auto it = std::find(materialNames.begin(), materialNames.end(), *name);
            materialId = std::int64_t(it - materialNames.begin());
            if (it == materialNames.end()) materialNames.push_back(*name);
        } else {
            anyWithout = true;
        }
        if (anyMaterial && anyWithout)
            throw r.error("material",
                          "region '" + entry->key + "': either every region names its material or none does");

        std::optional<std::array<double, 3>> omega;
        std::array<double, 3> omegaCentre{0, 0, 0};
        if (const Dictionary* spin = r.findDict("angularVelocity"))
            readAngularVelocity(*spin, dim, omega, omegaCentre);

        std::vector<std::pair<int, std::vector<double>>> values;
        if (const Dictionary* fields = r.findDict("fields")) {
            for (const auto& f : fields->entries()) {
                std::vector<double> v;
                // A bare number is a scalar, a parenthesised list a vector (also in 1D, where both have
                // one component): recorded as 0 or dim in fieldComponents.
                const bool scalar = f->tokens.size() == 1 && f->tokens[0].isNumber();
                const int components = scalar ? 0 : dim;
                if (scalar) {
                    v = {fields->get<double>(f->key)};
                } else {
                    v = fields->get<std::vector<double>>(f->key);
                    if (int(v.size()) < dim)
                        throw fields->error(f->key, "expected a scalar or a vector of " +
                                                        std::to_string(dim) + " components");
                    for (std::size_t k = dim; k < v.size(); ++k)
                        if (v[k] != 0)
                            throw fields->error(f->key, "component " + std::to_string(k + 1) +
                                                            " is non-zero in a " + std::to_string(dim) +
                                                            "D case");
                    v.resize(dim);
                }
                if (f->key == "position" || f->key == "globalId" || f->key == "region" || f->key == "mass" ||
                    f->key == "material")
                    throw fields->error(f->key, "'" + f->key + "' is set by particleGen itself");
                int index = -1;
                for (std::size_t k = 0; k < fieldNames.size(); ++k)
                    if (fieldNames[k] == f->key) index = int(k);
                if (index < 0) {
                    index = int(fieldNames.size());
                    fieldNames.push_back(f->key);
                    fieldComponents.push_back(components);
                } else if (fieldComponents[index] != components) {
                    throw fields->error(
                        f->key, "field '" + f->key + "' is a scalar in one region and a vector in another");
                }
                values.emplace_back(index, v);
            }
        }
        // Rigid rotation adds ω × (x − c) to the velocity, which becomes a field if not one yet.
        std::size_t velocityValue = values.size();
        if (omega) {
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
                if (values[k].first == index) velocityValue = k;
            if (velocityValue == values.size()) values.emplace_back(index, std::vector<double>(dim, 0.0));
        }

        const std::int64_t regionId = std::int64_t(regionNames.size());
        regionNames.push_back(entry->key);
        if (takeOver) {
            std::erase_if(all, [&](const Particle& p) { return shape->inside(p.x.data()); });
        }
        const auto points = lattice->points(shape->bounds());
        // Per point: the same for most lattices, smaller on the faces of a nodal one.
        const auto volumes = lattice->pointVolumes(shape->bounds(), points);
        RegionReport rep{entry->key, 0, 0, shape->volume().value_or(-1), 0, lattice->spacing()};
        for (std::size_t p = 0; p * dim < points.size(); ++p) {
            std::vector<double> x(points.begin() + long(p * dim), points.begin() + long((p + 1) * dim));
            if (!shape->inside(x.data())) continue;
            const double mass = density * volumes[p];
            all.push_back({x, regionId, mass, values, materialId, density});
            if (omega) {
                const auto& w = *omega;
                double r3[3] = {0, 0, 0};
                for (int c = 0; c < dim; ++c) r3[c] = x[c] - omegaCentre[c];
                const double spin[3] = {w[1] * r3[2] - w[2] * r3[1], w[2] * r3[0] - w[0] * r3[2],
                                        w[0] * r3[1] - w[1] * r3[0]};
                auto& v = all.back().values[velocityValue].second;
                for (int c = 0; c < dim; ++c) v[c] += spin[c];
            }
            ++rep.count;
            rep.volume += volumes[p];
            rep.mass += mass;
        }
        if (rep.count == 0)
            throw r.error("shape", "region '" + entry->key + "' is empty: no lattice point of spacing " +
                                       std::to_string(lattice->spacing()) + " falls inside its shape");
        report_.push_back(rep);
    }

    // Counts after later regions took particles over.
    for (auto& rep : report_) rep.count = 0, rep.mass = 0, rep.volume = 0;
    std::vector<double> pointVolume(report_.size());
    for (const auto& p : all) {
        auto& rep = report_[p.region];
        ++rep.count;
        rep.mass += p.mass;
    }
    for (std::size_t k = 0; k < report_.size(); ++k) {
        const Dictionary& r = regions.subDict(report_[k].name);
        report_[k].volume = report_[k].mass / r.get<double>("density");
    }

    return withDimension(dim, [&](auto d) -> std::unique_ptr<ParticleSetBase> {
        constexpr int Dim = decltype(d)::value;
        auto set = std::make_unique<ParticleSet<Dim>>(all.size());
        set->regionNames = regionNames;
        if (anyMaterial) {
            set->materialNames = materialNames;
            auto& material = set->integerField("material");
            for (std::size_t i = 0; i < all.size(); ++i) material[i] = all[i].material;
        }
        auto& x = set->position();
        auto& id = set->globalId();
        auto& region = set->region();
        auto& mass = set->scalarField("mass");
        // The initial density is part of the state every method starts from (SPH evolves it;
        // the particle volume is m/rho).
        auto& density = set->scalarField("density");
        for (std::size_t i = 0; i < all.size(); ++i) {
            density[i] = all[i].density;
            for (int c = 0; c < Dim; ++c) x[i][c] = all[i].x[c];
            id[i] = std::int64_t(i);
            region[i] = all[i].region;
            mass[i] = all[i].mass;
        }
        for (std::size_t f = 0; f < fieldNames.size(); ++f) {
            if (fieldComponents[f] == 0) {
                auto& field = set->scalarField(fieldNames[f]);
                for (std::size_t i = 0; i < all.size(); ++i)
                    for (const auto& [index, v] : all[i].values)
                        if (index == int(f)) field[i] = v[0];
            } else {
                auto& field = set->vectorField(fieldNames[f]);
                for (std::size_t i = 0; i < all.size(); ++i)
                    for (const auto& [index, v] : all[i].values)
                        if (index == int(f))
                            for (int c = 0; c < Dim; ++c) field[i][c] = v[c];
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
