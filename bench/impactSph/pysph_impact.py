"""PySPH's 2D solid-mechanics impact example (pysph.examples.solid_mech.impact: steel disc on an
aluminium plate, Gaussian kernel cut at 3h, h = 1.3 dx, EPEC integrator) at a chosen lattice
spacing, for a fixed number of steps. Usage: python3 pysph_impact.py DX [PySPH options...]
e.g. python3 pysph_impact.py 1.5e-4 --max-steps 200 --disable-output -d out"""
import sys
import pysph.examples.solid_mech.impact as impact

dx = float(sys.argv.pop(1))
impact.dx = impact.dy = dx
impact.h = impact.hdx * dx

if __name__ == '__main__':
    impact.Impact().run()
