#include "geometry/ParticleGenerator.hpp"

#include "geometry/Lattice.hpp"
#include "geometry/Shape.hpp"
#include "particles/ParticleSet.hpp"

#include <cstdio>
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

}  // namespace

ParticleGenerator::ParticleGenerator(const Dictionary& dict) : dict_(dict), dimension_(dict.get<int>("dimension")) {
    if (dimension_ < 1 || dimension_ > 3) throw dict.error("dimension", "dimension must be 1, 2 or 3");
}

std::unique_ptr<ParticleSetBase> ParticleGenerator::generate() {
    const int dim = dimension_;
    const Dictionary& regions = dict_.subDict("regions");
    if (regions.size() == 0) throw regions.error("", "no regions defined");

    std::vector<std::string> fieldNames;  // union over regions, in order of first appearance
    std::vector<int> fieldComponents;
    struct Particle {
        std::vector<double> x;
        std::int64_t region;
        double mass;
        std::vector<std::pair<int, std::vector<double>>> values;
    };
    std::vector<Particle> all;
    std::vector<std::string> regionNames;
    report_.clear();

    for (const auto& entry : regions.entries()) {
        if (!entry->isDict()) throw regions.error(entry->key, "expected a region dictionary");
        const Dictionary& r = regions.subDict(entry->key);
        const auto shape = Shape::New(r.subDict("shape"), dim);
        const auto lattice = Lattice::New(r.subDict("lattice"), dim);
        const double density = r.get<double>("density");
        if (!(density > 0)) throw r.error("density", "density must be positive");
        const bool takeOver = r.getOrDefault<bool>("override", true);

        std::vector<std::pair<int, std::vector<double>>> values;
        if (const Dictionary* fields = r.findDict("fields")) {
            for (const auto& f : fields->entries()) {
                std::vector<double> v;
                if (f->tokens.size() == 1 && f->tokens[0].isNumber()) {
                    v = {fields->get<double>(f->key)};
                } else {
                    v = fields->get<std::vector<double>>(f->key);
                    if (int(v.size()) < dim)
                        throw fields->error(f->key, "expected a scalar or a vector of " + std::to_string(dim) + " components");
                    for (std::size_t k = dim; k < v.size(); ++k)
                        if (v[k] != 0) throw fields->error(f->key, "component " + std::to_string(k + 1) + " is non-zero in a " + std::to_string(dim) + "D case");
                    v.resize(dim);
                }
                if (f->key == "position" || f->key == "globalId" || f->key == "region" || f->key == "mass")
                    throw fields->error(f->key, "'" + f->key + "' is set by particleGen itself");
                int index = -1;
                for (std::size_t k = 0; k < fieldNames.size(); ++k)
                    if (fieldNames[k] == f->key) index = int(k);
                if (index < 0) {
                    index = int(fieldNames.size());
                    fieldNames.push_back(f->key);
                    fieldComponents.push_back(int(v.size()));
                } else if (fieldComponents[index] != int(v.size())) {
                    throw fields->error(f->key, "field '" + f->key + "' is a scalar in one region and a vector in another");
                }
                values.emplace_back(index, v);
            }
        }

        const std::int64_t regionId = std::int64_t(regionNames.size());
        regionNames.push_back(entry->key);
        if (takeOver) {
            std::erase_if(all, [&](const Particle& p) { return shape->inside(p.x.data()); });
        }
        const auto points = lattice->points(shape->bounds());
        const double mass = density * lattice->pointVolume();
        RegionReport rep{entry->key, 0, 0, shape->volume().value_or(-1), 0, lattice->spacing()};
        for (std::size_t p = 0; p * dim < points.size(); ++p) {
            std::vector<double> x(points.begin() + long(p * dim), points.begin() + long((p + 1) * dim));
            if (!shape->inside(x.data())) continue;
            all.push_back({x, regionId, mass, values});
            ++rep.count;
        }
        if (rep.count == 0)
            throw r.error("shape", "region '" + entry->key + "' is empty: no lattice point of spacing " +
                                       std::to_string(lattice->spacing()) + " falls inside its shape");
        rep.volume = double(rep.count) * lattice->pointVolume();
        rep.mass = double(rep.count) * mass;
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
        auto& x = set->position();
        auto& id = set->globalId();
        auto& region = set->region();
        auto& mass = set->scalarField("mass");
        for (std::size_t i = 0; i < all.size(); ++i) {
            for (int c = 0; c < Dim; ++c) x[i][c] = all[i].x[c];
            id[i] = std::int64_t(i);
            region[i] = all[i].region;
            mass[i] = all[i].mass;
        }
        for (std::size_t f = 0; f < fieldNames.size(); ++f) {
            if (fieldComponents[f] == 1) {
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
    std::snprintf(line, sizeof line, "%-20s %10s %14s %14s %14s %10s\n", "region", "particles", "volume", "exact volume",
                  "mass", "spacing");
    s << line;
    std::size_t total = 0;
    double mass = 0;
    for (const auto& r : report_) {
        char exact[32] = "-";
        if (r.exactVolume >= 0) std::snprintf(exact, sizeof exact, "%.6g", r.exactVolume);
        std::snprintf(line, sizeof line, "%-20s %10zu %14.6g %14s %14.6g %10.4g\n", r.name.c_str(), r.count, r.volume,
                      exact, r.mass, r.spacing);
        s << line;
        total += r.count;
        mass += r.mass;
    }
    std::snprintf(line, sizeof line, "%-20s %10zu %14s %14s %14.6g\n", "total", total, "", "", mass);
    s << line;
    return s.str();
}

}  // namespace mfdyn
