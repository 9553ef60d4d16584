// Zoltan's recursive coordinate bisection and Hilbert space-filling curve behind Partitioner.hpp.
// Zoltan (Devine et al., "Zoltan data management services for parallel dynamic applications",
// Computing in Science and Engineering 4(2), 2002) from Debian's libtrilinos-zoltan-dev: the
// partitioner LAMMPS-like codes write by hand, kept and tested by Sandia. PT-Scotch partitions
// graphs (the neighbour graph would have to be built and sent first); for particles whose
// neighbourhoods are spheres, a geometric cut is what the halo needs, and Zoltan's kept cuts
// answer the point and box queries of migration and halos directly.
#include "particles/Partitioner.hpp"

#include "core/Communicator.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <cstring>

#ifdef MFDYN_WITH_MPI
#include <mpi.h>
#include <zoltan.h>
#endif

namespace mfdyn {

const std::vector<std::string>& Partitioner::methods() {
    static const std::vector<std::string> names{"rcb", "hsfc"};
    return names;
}

#ifdef MFDYN_WITH_MPI
namespace {
// Zoltan's global ids are ZOLTAN_ID_TYPE words; an int64 id takes as many as it needs.
constexpr int idWords = int((sizeof(std::int64_t) + sizeof(ZOLTAN_ID_TYPE) - 1) / sizeof(ZOLTAN_ID_TYPE));
}  // namespace

struct Partitioner::Zoltan {
    Zoltan_Struct* zz = nullptr;
    int dimension = 3;
    const std::vector<double>* coordinates = nullptr;
    const std::vector<double>* weights = nullptr;
    const std::vector<std::int64_t>* globalIds = nullptr;

    static int count(void* data, int* error) {
        *error = ZOLTAN_OK;
        return int(static_cast<Zoltan*>(data)->globalIds->size());
    }
    static void list(void* data, int gidWords, int lidWords, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int weightDim,
                     float* weights, int* error) {
        auto& self = *static_cast<Zoltan*>(data);
        const std::size_t n = self.globalIds->size();
        for (std::size_t i = 0; i < n; ++i) {
            std::memset(gids + i * std::size_t(gidWords), 0, sizeof(ZOLTAN_ID_TYPE) * std::size_t(gidWords));
            std::memcpy(gids + i * std::size_t(gidWords), &(*self.globalIds)[i], sizeof(std::int64_t));
            if (lidWords > 0) lids[i * std::size_t(lidWords)] = ZOLTAN_ID_TYPE(i);
            if (weightDim > 0) weights[i] = float((*self.weights)[i]);
        }
        *error = ZOLTAN_OK;
    }
    static int geometryDimension(void* data, int* error) {
        *error = ZOLTAN_OK;
        return static_cast<Zoltan*>(data)->dimension;
    }
    static void geometry(void* data, int, int lidWords, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dim,
                         double* out, int* error) {
        auto& self = *static_cast<Zoltan*>(data);
        for (int k = 0; k < count; ++k) {
            const std::size_t i = lidWords > 0 ? std::size_t(lids[std::size_t(k) * std::size_t(lidWords)]) : std::size_t(k);
            for (int d = 0; d < dim; ++d)
                out[std::size_t(k) * std::size_t(dim) + std::size_t(d)] =
                    (*self.coordinates)[i * std::size_t(dim) + std::size_t(d)];
        }
        *error = ZOLTAN_OK;
    }
};

Partitioner::Partitioner(const std::string& method, int dimension, double imbalanceTolerance)
    : method_(method), dimension_(dimension), zoltan_(std::make_unique<Zoltan>()) {
    if (std::find(methods().begin(), methods().end(), method) == methods().end())
        throw InputError("unknown partitioning method '" + method + "'; valid methods: rcb, hsfc");
    static bool initialised = false;
    if (!initialised) {
        float version = 0;
        if (Zoltan_Initialize(0, nullptr, &version) != ZOLTAN_OK) throw Error("Zoltan_Initialize failed");
        initialised = true;
    }
    zoltan_->dimension = dimension;
    if (!Communicator::mpiBuilt() || !Communicator::distributed()) return;  // one rank: no Zoltan needed
    zoltan_->zz = Zoltan_Create(*static_cast<MPI_Comm*>(Communicator::nativeHandle()));
    Zoltan_Struct* zz = zoltan_->zz;
    Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
    Zoltan_Set_Param(zz, "LB_METHOD", method == "rcb" ? "RCB" : "HSFC");
    Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", std::to_string(idWords).c_str());
    Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
    Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", "1");
    Zoltan_Set_Param(zz, "RETURN_LISTS", "EXPORT");
    Zoltan_Set_Param(zz, "KEEP_CUTS", "1");
    Zoltan_Set_Param(zz, "IMBALANCE_TOL", std::to_string(imbalanceTolerance).c_str());
    Zoltan_Set_Num_Obj_Fn(zz, &Zoltan::count, zoltan_.get());
    Zoltan_Set_Obj_List_Fn(zz, &Zoltan::list, zoltan_.get());
    Zoltan_Set_Num_Geom_Fn(zz, &Zoltan::geometryDimension, zoltan_.get());
    Zoltan_Set_Geom_Multi_Fn(zz, &Zoltan::geometry, zoltan_.get());
}

Partitioner::~Partitioner() {
    if (zoltan_ && zoltan_->zz) Zoltan_Destroy(&zoltan_->zz);
}

std::vector<int> Partitioner::partition(const std::vector<double>& coordinates, const std::vector<double>& weights,
                                        const std::vector<std::int64_t>& globalIds) {
    std::vector<int> rank(globalIds.size(), Communicator::rank());
    partitioned_ = true;
    if (!zoltan_->zz) return rank;
    zoltan_->coordinates = &coordinates, zoltan_->weights = &weights, zoltan_->globalIds = &globalIds;
    int changes = 0, gidWords = 0, lidWords = 0, imports = 0, exports = 0;
    ZOLTAN_ID_PTR importGids = nullptr, importLids = nullptr, exportGids = nullptr, exportLids = nullptr;
    int *importProcs = nullptr, *importParts = nullptr, *exportProcs = nullptr, *exportParts = nullptr;
    const int status = Zoltan_LB_Partition(zoltan_->zz, &changes, &gidWords, &lidWords, &imports, &importGids,
                                           &importLids, &importProcs, &importParts, &exports, &exportGids,
                                           &exportLids, &exportProcs, &exportParts);
    if (status != ZOLTAN_OK) throw Error("Zoltan_LB_Partition (" + method_ + ") failed");
    for (int k = 0; k < exports; ++k) rank[std::size_t(exportLids[std::size_t(k) * std::size_t(lidWords)])] = exportProcs[k];
    Zoltan_LB_Free_Part(&importGids, &importLids, &importProcs, &importParts);
    Zoltan_LB_Free_Part(&exportGids, &exportLids, &exportProcs, &exportParts);
    zoltan_->coordinates = nullptr, zoltan_->weights = nullptr, zoltan_->globalIds = nullptr;
    return rank;
}

int Partitioner::owner(const double* x) const {
    if (!zoltan_->zz) return Communicator::rank();
    double point[3] = {0, 0, 0};
    for (int d = 0; d < dimension_; ++d) point[d] = x[d];
    int proc = 0, part = 0;
    if (Zoltan_LB_Point_PP_Assign(zoltan_->zz, point, &proc, &part) != ZOLTAN_OK)
        throw Error("Zoltan_LB_Point_PP_Assign failed");
    return proc;
}

std::vector<int> Partitioner::ranksTouching(const double* lo, const double* hi) const {
    if (!zoltan_->zz) return {Communicator::rank()};
    double low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
    for (int d = 0; d < dimension_; ++d) low[d] = lo[d], high[d] = hi[d];
    std::vector<int> procs(std::size_t(Communicator::size())), parts(std::size_t(Communicator::size()));
    int procCount = 0, partCount = 0;
    if (Zoltan_LB_Box_PP_Assign(zoltan_->zz, low[0], low[1], low[2], high[0], high[1], high[2], procs.data(),
                                &procCount, parts.data(), &partCount) != ZOLTAN_OK)
        throw Error("Zoltan_LB_Box_PP_Assign failed");
    procs.resize(std::size_t(procCount));
    std::sort(procs.begin(), procs.end());
    return procs;
}

#else  // serial build: one rank owns everything

struct Partitioner::Zoltan {};

Partitioner::Partitioner(const std::string& method, int dimension, double)
    : method_(method), dimension_(dimension), zoltan_(std::make_unique<Zoltan>()) {
    if (std::find(methods().begin(), methods().end(), method) == methods().end())
        throw InputError("unknown partitioning method '" + method + "'; valid methods: rcb, hsfc");
}
Partitioner::~Partitioner() = default;
std::vector<int> Partitioner::partition(const std::vector<double>&, const std::vector<double>&,
                                        const std::vector<std::int64_t>& globalIds) {
    partitioned_ = true;
    return std::vector<int>(globalIds.size(), 0);
}
int Partitioner::owner(const double*) const { return 0; }
std::vector<int> Partitioner::ranksTouching(const double*, const double*) const { return {0}; }

#endif

}  // namespace mfdyn
