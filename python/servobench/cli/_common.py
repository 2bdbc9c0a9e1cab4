"""Shared by the sub-commands: exit codes, errors, the --out folder (Output) and small helpers."""

from __future__ import annotations

import contextlib
import os
import sys

import numpy as np

from .. import _core, _serialise


EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2


class UsageError(Exception):
    """Bad options or input files: exit 2."""


class WorkFailed(Exception):
    """The work ran but did not succeed: exit 1."""


# ----------------------------------------------------------------------------------------------------------------
# Output helpers
# ----------------------------------------------------------------------------------------------------------------
class Output:
    """The --out folder, the plot format and the record of what was written."""

    def __init__(self, args, stem: str):
        self.dir = args.out
        self.fmt = args.format
        self.stem = stem
        self.quiet = args.quiet
        self.written: list[str] = []

    def path(self, what: str, ext: str) -> str:
        os.makedirs(self.dir, exist_ok=True)
        return os.path.join(self.dir, f"{self.stem}_{what}.{ext}")

    def done(self, path: str, what: str) -> None:
        self.written.append(path)
        print(f"wrote {path}  ({what})")

    def csv(self, what: str, columns: dict, units: dict, doc: str) -> str:
        """Writes columns (name -> 1-D array) with a header 'name [unit]'."""
        p = self.path(what, "csv")
        names = list(columns)
        data = np.column_stack([np.asarray(columns[n], dtype=float) for n in names])
        header = ",".join(f"{n} [{units[n]}]" if units.get(n) else n for n in names)
        np.savetxt(p, data, delimiter=",", header=header, comments="", fmt="%.10g")
        self.done(p, doc)
        return p

    def json(self, what: str, obj: dict, doc: str) -> str:
        p = self.path(what, "json")
        with open(p, "w", encoding="utf-8") as f:
            f.write(_serialise.dumps(obj, indent=2) + "\n")
        self.done(p, doc)
        return p

    def figure(self, what: str, fig, doc: str) -> str:
        from ..plot import Plot

        fig = fig.figure if isinstance(fig, Plot) else fig
        p = self.path(what, self.fmt)
        fig.savefig(p, dpi=110)
        import matplotlib.pyplot as plt

        plt.close(fig)
        self.done(p, doc)
        return p


def _margins_dict(m) -> dict:
    import dataclasses

    return dataclasses.asdict(m)


def _linearity_note(axis, measured: dict | None, analytic: dict | None, amplitude_pulse,
                    tolerance_deg: float = 3.0) -> str:
    """Why a measured phase margin differs from the analytic one by more than ``tolerance_deg``: the analytic loop
    linearises the plant (friction, cogging, unbalance and load torques are left out), so a small sweep amplitude
    on a plant with friction measures a different loop. Empty when they agree or a margin is missing."""
    try:
        pm_m, pm_a = float(measured["phase_margin_deg"]), float(analytic["phase_margin_deg"])
    except (TypeError, KeyError, ValueError):
        return ""
    if not (np.isfinite(pm_m) and np.isfinite(pm_a)) or abs(pm_m - pm_a) <= tolerance_deg:
        return ""
    fields = ("coulomb_nm", "static_nm", "motor_coulomb_nm", "motor_static_nm", "load_coulomb_nm",
              "load_static_nm", "cogging_nm", "unbalance_nm", "load_nm")
    nonlinear = [f"{f} {getattr(axis.plant, f):g} N*m" for f in fields if getattr(axis.plant, f, 0.0)]
    amp = "the automatic amplitude" if amplitude_pulse is None else f"{amplitude_pulse:g} pulse"
    why = (f"the plant has {', '.join(nonlinear)}, which the analytic loop leaves out; at {amp} "
           f"of sine amplitude they are a large share of the torque (a larger --amplitude-pulse measures closer to "
           f"the linear loop)") if nonlinear else \
        "the plant is linear: look at the sweep's coherence and the DAC/encoder quantisation at this amplitude"
    return (f"measured phase margin {pm_m:.1f} deg differs from the analytic {pm_a:.1f} deg by "
            f"{pm_m - pm_a:+.1f} deg: {why}")


def _progress(args):
    """progress= argument for the library: a text bar on stderr when wanted (L5)."""
    if args.quiet:
        return None
    return True if (args.progress or sys.stderr.isatty()) else None


def _fit_progress(args):
    """callback(iteration, cost) for the fit: a tqdm counter on stderr when wanted (L5, W7)."""
    from .._progress import iterations

    return iterations(_progress(args), "Identification")


@contextlib.contextmanager
def _bad_input(what: str):
    """ValueError/TypeError raised while building from options -> a usage error naming them."""
    try:
        yield
    except (ValueError, TypeError) as e:
        raise UsageError(f"{what}: {e}") from None


def _load(path: str):
    """(Axis, the file's dict) of an axis file."""
    from ..axisfile import axis_from_dict, read_axis

    data = read_axis(path)
    return axis_from_dict(data, path), data


def _stem(path: str) -> str:
    return os.path.splitext(os.path.basename(path))[0]


def _drive_mode(axis) -> str:
    from .. import _core

    return {_core.TorqueDrive: "torque", _core.VelocityDrive: "velocity", _core.ServoPositionDrive: "position",
            _core.StepperDrive: "stepper"}.get(type(axis.drive), type(axis.drive).__name__)


def _need_voltage_output(axis, path, command):
    mode = _drive_mode(axis)
    if mode not in ("torque", "velocity"):
        raise UsageError(f"{path}: drive.mode: {command} needs the card's position loop, i.e. a voltage-output axis "
                         f"(drive.mode = \"torque\" or \"velocity\"); this axis's drive is \"{mode}\" (pulse input, "
                         "the servo law is bypassed)")
