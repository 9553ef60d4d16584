"""PySPH's oscillating plate (pysph.examples.solid_mech.oscillating_plate: Gray, Monaghan and Swift
2001; L = 0.2, H = 0.02, dx = 0.002, h = 1.3 dx, cubic spline, ElasticSolidsScheme, EPEC, dt 1e-5)
as it is, with the time loop timed in wall AND process CPU seconds (PySPH's own "Run took" is wall
only), and the mean neighbour count of the plate particles (plate and wall sources within the
cubic spline's support 2h). Usage: python3 pysph_plate.py [PySPH options...]
e.g. /usr/bin/python3 pysph_plate.py --tf 0.02 --no-openmp --disable-output -d out"""
import time

import numpy as np
from pysph.examples.solid_mech.oscillating_plate import OscillatingPlate


class TimedPlate(OscillatingPlate):
    def solve(self):
        cpu0, wall0 = time.process_time(), time.perf_counter()
        super().solve()
        cpu1, wall1 = time.process_time(), time.perf_counter()
        arrays = {p.name: p for p in self.particles}
        plate = arrays["plate"]
        xs = np.concatenate([p.x for p in self.particles])
        ys = np.concatenate([p.y for p in self.particles])
        support = 2.0 * self.h
        neighbours = 0
        for x, y in zip(plate.x, plate.y):
            neighbours += np.count_nonzero((xs - x) ** 2 + (ys - y) ** 2 < support * support)
        print("Timed loop: steps %d, t %.6g, wall %.5f s, cpu %.5f s, plate particles %d, "
              "all particles %d, neighbours per plate particle %.2f (self included, within 2h)"
              % (self.solver.count, self.solver.t, wall1 - wall0, cpu1 - cpu0, plate.get_number_of_particles(),
                 len(xs), neighbours / plate.get_number_of_particles()))


if __name__ == '__main__':
    TimedPlate().run()
