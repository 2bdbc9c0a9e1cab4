"""The robust-tuning figure of docs/howto-batch.md (issue 22 point 3): phase margin and overshoot over 200 drawn
plants of the demo axis, with the nominal model-based design and with sb.tune_robust's. Run by
tests/python/test_tune_robust.py (into a temporary folder) and by hand to refresh docs/img/robust_tuning.png:

    python docs/make_robust_figures.py [output folder, default docs/img]
"""

from __future__ import annotations

import sys
from pathlib import Path

SPREAD = {"plant.inertia_kgm2": (0.7e-4, 2.0e-4), "plant.coulomb_nm": (0.002, 0.01)}  # kg*m^2, N*m


def figure(out_dir: Path):
    """Tunes the demo axis for the spread, saves robust_tuning.png into out_dir; returns (result, data drawn)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import servobench as sb

    robust = sb.tune_robust(sb.demo_axis(), spread=SPREAD, n=200, seed=2, objective="phase_margin",
                            phase_margin_deg=50)
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.5))
    drawn = robust.plot(ax=ax)
    fig.suptitle(f"200 plants, J {SPREAD['plant.inertia_kgm2']} kg*m^2, Coulomb {SPREAD['plant.coulomb_nm']} N*m: "
                 "nominal vs robust design", fontsize=9)
    fig.tight_layout()
    out_dir.mkdir(parents=True, exist_ok=True)
    fig.savefig(out_dir / "robust_tuning.png", dpi=80)
    plt.close(fig)
    return robust, drawn


if __name__ == "__main__":
    res, _ = figure(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent / "img")
    print(res)
