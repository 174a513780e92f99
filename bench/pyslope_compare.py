"""Time PySlope (Bishop's method, the Python package engineers reach for) on a critical-circle
search of a 2:1 embankment, for the README's comparison with thrustline's search.

Usage: python3 bench/pyslope_compare.py   (installs pyslope from PyPI if it is missing)
"""
import importlib
import subprocess
import sys
import time

try:
    pyslope = importlib.import_module("pyslope")
except ImportError:
    subprocess.check_call([sys.executable, "-m", "pip", "install", "-q", "pyslope"])
    pyslope = importlib.import_module("pyslope")



def search():
    """PySlope's search of the dry 2:1 embankment: (milliseconds, least F, circles analysed, as
    its search table holds them)."""
    slope = pyslope.Slope(height=30.48, angle=None, length=60.96)
    slope.set_materials(pyslope.Material(unit_weight=10, friction_angle=40, cohesion=6.096,
                                         depth_to_bottom=100))
    slope.update_analysis_options(slices=50, iterations=2500)
    start = time.perf_counter()
    slope.analyse_slope()
    return (time.perf_counter() - start) * 1e3, slope.get_min_FOS(), len(slope._search)


if __name__ == "__main__":
    ms, f, circles = search()
    print(f"pyslope: {circles} circles x 50 slices (Bishop): {ms:.0f} ms, min F = {f:.4f}")
