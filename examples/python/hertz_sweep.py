"""A parameter sweep: the Hertz ball at several forces, computed against closed form.

    PYTHONPATH=build/python python3 examples/python/hertz_sweep.py
"""
import pathlib

import bemcontact as bc

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]

problem = bc.Problem.load(EXAMPLES / "contact_hertz_sphere.toml")
print(f"{'P':>8} {'a':>10} {'a Hertz':>10} {'error %':>8} {'p0':>10} {'p0 Hertz':>10}")
for force in (5.0, 10.0, 20.0, 31.5, 40.0):
    result = problem.run(P=force)
    contact = result.summary["results"]["contact"]
    hertz = contact["reference"]
    print(f"{force:8.2f} {contact['a']:10.5f} {hertz['a']:10.5f} {100 * (contact['a'] / hertz['a'] - 1):8.2f} "
          f"{contact['centre_pressure']:10.1f} {hertz['p0']:10.1f}")
