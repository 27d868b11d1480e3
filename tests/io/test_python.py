"""The Python package (python/) against real runs: test_python.py SLUICE SOURCE_DIR WORK.

Runs scenes with overrides through sluice.run, reads the files back with
sluice.Output and checks what a Python user relies on: the summary matches
the file, the solids inventory is conserved to round-off and the CSV holds
the very numbers of the HDF5 file, strings are str (variable-length UTF-8),
every field has units, cell fields come with their cell centres, a steady
run's .xmf is the single uniform grid meshio reads, and bad input raises
with the message. Exit 77 (skipped) without h5py or numpy."""
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"skipped: {e.name} is not installed (Debian: apt-get install python3-h5py python3-numpy)")
    sys.exit(77)

S, SRC, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(SRC, "python"))
import sluice  # noqa: E402

os.makedirs(WORK, exist_ok=True)
os.chdir(WORK)
passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAILED: {what}")


# ---- a transient run: the fluidised bed column, ended early by an override
s = sluice.run(os.path.join(SRC, "configs/fluidized_bed.ini"), set={"time.end": 20, "output.every": 5},
               output="bed.h5", binary=S)
check(s["status"] == "done" and s["exit_code"] == 0, f"status {s['status']}")
check(abs(s["t_reached"] - 20) < 1e-9 and s["t_end"] == 20, f"t_reached {s['t_reached']}, t_end {s['t_end']}")
with sluice.Output(s["output"]) as out:
    check(len(out.times) == s["output_times"] == 5, f"{len(out.times)} output times, summary {s['output_times']}")
    check(abs(out.times[-1] - 20) < 1e-9 and out.times[0] == 0, f"times {out.times}")
    sc = out.scalars()
    inv = sc["solids_inventory"]
    spread = (inv.max() - inv.min()) / inv[0]
    print(f"solids inventory {inv[0]:.17g} m, relative spread over {len(inv)} output times {spread:.2e}")
    check(spread < 1e-12, f"inventory not conserved: spread {spread:.3e}")
    check(np.all(np.abs(sc["solids_conservation_error"]) < 1e-12), "conservation error")
    check(out.scalar_units["solids_inventory"] == "m" and out.units("mixture_flux") == "m/s", "scalar units")
    cols, units = sluice.read_scalars_csv("bed_scalars.csv")
    check(np.array_equal(cols["time"], out.times), "CSV times = HDF5 times")
    check(all(np.array_equal(cols[k], v, equal_nan=True) for k, v in sc.items()), "CSV values = HDF5 attributes")
    check(units["time"] == "s" and units["solids_inventory"] == "m", f"CSV units {units}")
    phi = out.field("phi")
    xc = out.points("phi")
    check(out.centring("phi") == "cell" and xc.shape == (len(phi), 3), f"phi {phi.shape}, points {xc.shape}")
    mid = out.coordinates[out.cells].mean(axis=1)
    check(np.allclose(xc, mid, rtol=0, atol=1e-15), "1-D cell centres are the midpoints")
    check(out.units("phi") == "1" and out.units("velocity_solid") == "m/s", "field units")
    with h5py.File("bed.h5", "r", locking=False) as f:
        prov = f["provenance"].attrs["sluice_version"]
        check(isinstance(prov, str), f"provenance string is {type(prov).__name__}, not str")
        check(f["provenance/ini"].asstr()[()].count("[scene]") == 1, "the resolved INI")
        missing = [f"{g}/{k}" for g in f if g.startswith("step_") for k in f[g]
                   if not isinstance(f[g][k].attrs.get("units"), str)]
        check(not missing, f"fields without units: {missing[:3]}")
    check("[scene]" in out.provenance["ini"], "Output.provenance")

# ---- a steady run: one output time, one uniform grid (what meshio.read opens)
s = sluice.run(os.path.join(SRC, "configs/cavity_stokes.ini"), set={"mesh.cells": [8, 8]}, output="cavity.h5",
               binary=S)
check(s["converged"] is True and s["output_times"] == 1, f"converged {s['converged']}")
root = ET.parse("cavity.xmf").getroot()
domain = list(root)
grids = list(domain[0]) if len(domain) == 1 else []
ok = len(grids) == 1 and grids[0].get("GridType") == "Uniform"
ok = ok and all(c.tag in ("Topology", "Geometry", "Attribute") for c in grids[0])
ok = ok and all(c.get("Center") in ("Node", "Cell") for c in grids[0] if c.tag == "Attribute")
check(ok, "cavity.xmf is one uniform grid of Topology, Geometry and node/cell Attributes")
with sluice.Output("cavity.h5") as out:
    x, u = out.coordinates, out.field("velocity")
    lid = (np.abs(x[:, 1] - 1) < 1e-12) & (x[:, 0] > 1e-12) & (x[:, 0] < 1 - 1e-12)
    check(lid.sum() == 15 and np.max(np.abs(u[lid] - [1, 0, 0])) < 1e-12, "the lid moves at (1, 0)")
    check(out.units("pressure") == "Pa", "pressure in Pa")
try:
    import meshio
except ImportError:
    print("meshio not installed: meshio.read not tried")
else:
    m = meshio.read("cavity.xmf")
    check(m.point_data["velocity"].shape == (len(x), 3), "meshio.read")
    # a transient navier_stokes run (no scalars): meshio's time-series reader
    sluice.run(os.path.join(SRC, "configs/cavity_stokes.ini"),
               set={"mesh.cells": [4, 4], "time.scheme": "bdf1", "time.adaptive": False, "time.dt": 0.1,
                    "time.end": 0.3, "output.every": 0.1}, output="cavity_t.h5", binary=S)
    with meshio.xdmf.TimeSeriesReader("cavity_t.xmf") as r:  # (h5py: one locking mode per file and process)
        r.read_points_cells()
        ts = [r.read_data(k)[0] for k in range(r.num_steps)]
        u_last = r.read_data(r.num_steps - 1)[1]["velocity"]
    with sluice.Output("cavity_t.h5") as out:
        check(np.array_equal(ts, out.times) and len(ts) == 4, f"meshio times {ts}, file {out.times}")
        check(np.array_equal(u_last, out.field("velocity")), "meshio reads the last velocity")

# ---- bad input raises with the message; nothing is written
try:
    sluice.run(os.path.join(SRC, "configs/cavity_stokes.ini"), set={"time.ennd": 3}, output="never.h5", binary=S)
    check(False, "bad input did not raise")
except sluice.SluiceError as e:
    check(e.exit_code == 2 and "did you mean 'end'" in e.message, f"exit {e.exit_code}: {e.message}")
    check(e.summary["status"] == "bad input" and not os.path.exists("never.h5"), "bad input summary")

# ---- pip install ./python (offline: no build isolation), then import from there
import shutil  # noqa: E402

target, copy = os.path.join(WORK, "site"), os.path.join(WORK, "python_src")  # the build leaves files beside the source
shutil.rmtree(copy, ignore_errors=True)
shutil.copytree(os.path.join(SRC, "python"), copy, ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
r = subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-build-isolation", "--no-deps",
                    "--target", target, copy], capture_output=True, text=True)
if r.returncode == 0:
    r = subprocess.run([sys.executable, "-c", "import sluice, sys; print(sluice.__file__)"], capture_output=True,
                       text=True, env=dict(os.environ, PYTHONPATH=target))
    check(r.returncode == 0 and r.stdout.startswith(target), f"installed package imports: {r.stdout}{r.stderr}")
else:
    print(f"pip install not tried: {r.stderr.strip().splitlines()[-1] if r.stderr.strip() else r.returncode}")

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
