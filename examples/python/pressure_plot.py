"""A plot: the contact pressure of the Hertz ball against Hertz's, for three meshes.

    PYTHONPATH=build/python python3 examples/python/pressure_plot.py [OUTPUT.png]
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import bemcontact as bc  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
output = sys.argv[1] if len(sys.argv) > 1 else "hertz_pressure.png"

problem = bc.Problem.load(EXAMPLES / "contact_hertz_sphere.toml")
fig, ax = plt.subplots(figsize=(7, 4.5))
for elements in (15, 30, 60):
    result = problem.run(contact_elements=elements)
    pairs = result.contact()
    ax.plot(pairs["coordinate"], -pairs["p_n"], "o-", ms=3, label=f"{elements} contact elements")
hertz = result.summary["results"]["contact"]["reference"]
r = np.linspace(0.0, hertz["a"], 200)
ax.plot(r, hertz["p0"] * np.sqrt(1.0 - (r / hertz["a"]) ** 2), "k--", label="Hertz")
ax.set_xlabel("r")
ax.set_ylabel("contact pressure")
ax.legend()
fig.tight_layout()
fig.savefig(output)
print(f"wrote {output}")
