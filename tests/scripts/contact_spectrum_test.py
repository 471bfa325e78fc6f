#!/usr/bin/python3
"""Checks bench/contact_spectrum.py against dense eigenvalues on a small contact.

  contact_spectrum_test.py HALFSPACE_EXECUTABLE SOURCE_DIR WORK_DIR
"""

import importlib.util
import pathlib
import subprocess
import sys

import numpy as np

executable, source, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
work.mkdir(parents=True, exist_ok=True)
script = source / "bench" / "contact_spectrum.py"
spec = importlib.util.spec_from_file_location("contact_spectrum", script)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)

surface, result = work / "spectrum-surface.h5", work / "spectrum-result.h5"
subprocess.run([executable, "generate", "--kind", "self-affine", "--grid", "32x32", "--size", "32e-6", "--hurst",
                "0.8", "--rms-slope", "0.1", "--seed", "3", "--output", str(surface)], check=True,
               stdout=subprocess.DEVNULL)
subprocess.run([executable, "solve", "--height-map", str(surface), "--boundary", "periodic", "--E-star", "1e9",
                "--mean-pressure", "1e7", "--output", str(result)], check=True, stdout=subprocess.DEVNULL)

contact, dx, dy = module.read_contact_set(str(result))
ops = module.Operators(contact.shape, dx, dy)
restricted_k = lambda v: contact * ops.apply(ops.kernel, contact * v)
fourier = module.fourier_preconditioner(ops, contact)
balancing = module.balancing_preconditioner(ops, contact, 8, restricted_k, fourier)
cells = np.flatnonzero(contact.ravel())
assert 10 < len(cells) < contact.size, f"unsuitable contact set: {len(cells)} cells"


def dense(operator):
    columns = []
    for cell in cells:
        unit = np.zeros(contact.size)
        unit[cell] = 1.0
        columns.append(operator(unit.reshape(contact.shape)).ravel()[cells])
    return np.array(columns).T


failures = []
k_cc = dense(restricted_k)
for name, preconditioner in (("fourier", fourier), ("balancing 8", balancing)):
    exact = np.sort(np.linalg.eigvals(dense(preconditioner) @ k_cc).real)
    low, high, _ = module.lanczos_spectrum(restricted_k, preconditioner, contact, len(cells))
    # Lanczos bounds lie inside the spectrum and converge to its ends first.
    for label, estimate, truth in (("min", low, exact[0]), ("max", high, exact[-1])):
        if abs(estimate - truth) > 0.02 * truth:
            failures.append(f"{name}: Lanczos {label} {estimate:.5f} against dense {truth:.5f}")
    print(f"{name}: dense {exact[0]:.4f}..{exact[-1]:.4f}, Lanczos {low:.4f}..{high:.4f}")

# The balancing correction cannot raise the top of the spectrum here.
if not module.lanczos_spectrum(restricted_k, balancing, contact, 100)[1] <= \
        module.lanczos_spectrum(restricted_k, fourier, contact, 100)[1] * 1.001:
    failures.append("balancing raised the largest eigenvalue")

bad = subprocess.run([sys.executable, str(script), str(surface)], capture_output=True, text=True)
if bad.returncode != 2 or "not a halfspace result file" not in bad.stderr:
    failures.append(f"a height map was not refused: exit {bad.returncode}, stderr {bad.stderr!r}")

for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
