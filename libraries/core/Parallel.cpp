#include "core/Parallel.hpp"

#include <omp.h>

namespace mfdyn {

int threadCount() {
    return omp_get_max_threads();
}

}  // namespace mfdyn
