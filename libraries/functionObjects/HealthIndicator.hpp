#pragma once
// What a solver tells the health check (Health.hpp) beyond its fields: indicators of a degrading
// discretisation that only the method can compute (a kernel sum, a correction matrix, the pair
// separations), and the box its particles must stay in.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace mfdyn {

// One indicator as of now. `name` is one word (a CSV column stem); `value` the worst over the
// particles (largest, or smallest where `definition` says so); `count` how many particles are past
// the method's threshold (summed over every rank); `worst` the global id of the worst particle
// (-1: none). `definition` says what is measured, the threshold and the source, for the log.
struct HealthIndicator {
    std::string name;
    double value = 0.0;
    std::size_t count = 0;
    std::int64_t worst = -1;
    std::string definition;
};

// An axis-aligned box (unused components of a 1D or 2D run are ignored).
struct DomainBox {
    std::array<double, 3> min{}, max{};
};

}  // namespace mfdyn
