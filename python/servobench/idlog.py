"""Reading real identification records: unit tags, column mapping, real time vectors, linear axes.

One reader for Python and the command line (``servobench identify --log``): a table (a pandas DataFrame, a CSV file
read by pandas, or the variables of a MATLAB ``.mat`` file read by :func:`scipy.io.loadmat`) is mapped column by
column -- time, command (torque, force or voltage), measured position or speed, optional reference -- and every
column's unit is read from, in this order: the ``units=`` argument, a tag in its header (``position [mm]``), or the
suffix of a house column name (``time_s``, ``torque_nm``, ``position_pulse``). A unit that is unknown, or of the
wrong kind for the column (``[deg]`` on a linear axis's position), is refused with an error naming the column; it is
never ignored.

Units and their SI factor (linear axes: m, N; rotary axes: rad, N*m):

============  ==========================================================
time          s, ms, us
position      m, mm, um (linear); rad, deg, rev (rotary); pulse/count (either, with the count size)
speed         m/s, mm/s (linear); rad/s, deg/s, rpm, rev/s (rotary); pulse/s
command       N, kN, mN (linear); N*m, Nm, mN*m (rotary); V, mV (with the drive gain, N/V or N*m/V)
============  ==========================================================

Time vectors: the sample period is the median step; steps within +-100 ppm of it are jitter (reported as
``time_jitter_ppm``), a step beyond 1.5 periods is a gap and a step <= 0 is non-monotonic time (errors naming the
sample); anything in between is irregular sampling (an error: resample first).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._log_tables import (MAX_JITTER_PPM, UNITS, _norm, check_time, column_unit, detect_count, finite_column,
                          motor_side, motor_side_line, parse_header, read_csv, read_dataframe, read_mat, unit_factor)
from ._serialise import JsonResult, dataframe

__all__ = ["read_csv", "read_dataframe", "read_mat", "column_unit", "finite_column", "detect_count",
           "UNITS", "parse_header", "unit_factor", "check_time", "MAX_JITTER_PPM", "IdentificationLog", "motor_side", "motor_side_line"]

# The unit tables, the column checks and the readers live in _log_tables.py (one concept per file, decision OR2);
# this module stays their home (the docs name them here).
for _f in (check_time, column_unit, detect_count, finite_column, motor_side, motor_side_line, parse_header, read_csv,
           read_dataframe, read_mat, unit_factor):
    _f.__module__ = __name__
del _f


# ----------------------------------------------------------------------------------------------------------------
# The log
# ----------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class IdentificationLog(JsonResult):
    """One identification experiment, sample k at t = k Ts.

    torque_nm
        the drive's effort held over [t_k, t_k+1): torque, N*m, on a rotary axis; force, N, on a linear axis
        (``linear=True``; also available as :attr:`force_n`).
    measured
        position (rad, or m on a linear axis) or speed (rad/s, m/s) at t_k, as `measured_is_speed` says; on the motor
        or the load.
    sample_period_s
        Ts, s. counts_per_rev: the encoder's resolution (one count is the residual unit of a fit); on a linear axis
        ``count_m`` (one count, m) takes its place.
    current_bw_hz
        the drive's current-loop bandwidth, Hz (known; ``inf`` for an ideal loop).
    reference
        the closed loop's position reference per sample (same unit as `measured`), or None: a closed-loop record
        keeps it for validation and instrumental variables.
    linear, count_m, lead_m_per_rev
        a linear axis (m, N, kg): one count in m, and the screw lead / gear ratio to the motor side (m of travel per
        motor revolution) where the user has one (:meth:`to_motor_side`).
    time_jitter_ppm
        the largest deviation of a real time vector's steps from its period (reported, accepted up to
        :data:`MAX_JITTER_PPM`).
    """

    sample_period_s: float
    torque_nm: np.ndarray
    measured: np.ndarray
    measured_is_speed: bool = False
    measured_on_load: bool = False
    counts_per_rev: float = 10000.0
    current_bw_hz: float = math.inf
    substeps: int = 1
    extra: dict = field(default_factory=dict, repr=False)
    reference: np.ndarray | None = field(default=None, repr=False)
    linear: bool = False
    count_m: float | None = None
    lead_m_per_rev: float | None = None
    time_jitter_ppm: float = 0.0

    def __post_init__(self):
        for name in ("torque_nm", "measured"):
            a = np.asarray(getattr(self, name), dtype=float)
            if a.ndim != 1:
                raise ValueError(f"IdentificationLog.{name} must be a 1-D array")
            bad = np.flatnonzero(~np.isfinite(a))
            if len(bad):
                raise ValueError(f"IdentificationLog.{name}[{bad[0]}] = {a[bad[0]]} is not a finite number "
                                 f"({len(bad)} such samples)")
            object.__setattr__(self, name, a)
        if len(self.torque_nm) != len(self.measured):
            raise ValueError(f"IdentificationLog: torque_nm has {len(self.torque_nm)} samples but measured has "
                             f"{len(self.measured)}; they must have the same length")
        if self.reference is not None:
            r = finite_column("reference", self.reference)
            if len(r) != len(self.measured):
                raise ValueError(f"IdentificationLog.reference has {len(r)} samples, measured {len(self.measured)}")
            object.__setattr__(self, "reference", r)
        if not (self.sample_period_s > 0 and math.isfinite(self.sample_period_s)):
            raise ValueError(f"IdentificationLog.sample_period_s = {self.sample_period_s} must be > 0")
        for name in ("count_m", "lead_m_per_rev"):
            v = getattr(self, name)
            if v is not None and not (math.isfinite(v) and v > 0):
                raise ValueError(f"IdentificationLog.{name} = {v} must be a finite number > 0 (m)")
        if not (math.isfinite(self.counts_per_rev) and self.counts_per_rev > 0):
            raise ValueError(f"IdentificationLog.counts_per_rev = {self.counts_per_rev} must be a finite number > 0")
        if not (0 <= self.time_jitter_ppm <= MAX_JITTER_PPM):
            raise ValueError(f"IdentificationLog.time_jitter_ppm = {self.time_jitter_ppm} must be in "
                             f"0..{MAX_JITTER_PPM:g}")

    @property
    def time_s(self) -> np.ndarray:
        """t_k = k Ts, s."""
        return np.arange(len(self.measured)) * self.sample_period_s

    @property
    def count_rad(self) -> float:
        """One encoder count in the measurement's unit: rad (rotary) or m (linear: count_m; 1 um if unknown)."""
        if self.linear:
            return self.count_m if self.count_m is not None else 1e-6
        return 2 * np.pi / self.counts_per_rev

    @property
    def measurement_count(self) -> float:
        """One encoder count in the unit of `measured`: :attr:`count_rad` (rad or m) for a position log, one count
        per sample period (rad/s or m/s) for a speed log. The scale the fits report their residuals in, in counts."""
        return self.count_rad / self.sample_period_s if self.measured_is_speed else self.count_rad

    @property
    def force_n(self) -> np.ndarray:
        """The effort on a linear axis, N (the same array as torque_nm)."""
        return self.torque_nm

    @property
    def units(self) -> dict:
        """The unit of each signal: position, speed, effort, inertia, time."""
        if self.linear:
            return {"position": "m", "speed": "m/s", "effort": "N", "inertia": "kg", "time": "s"}
        return {"position": "rad", "speed": "rad/s", "effort": "N*m", "inertia": "kg*m^2", "time": "s"}

    def __len__(self) -> int:
        return len(self.measured)

    def to_dataframe(self):
        """The log as a pandas DataFrame in the house column names :meth:`from_dataframe` reads: ``time_s`` (s),
        ``torque_nm`` (N*m; ``force_n``, N, on a linear axis), the measured signal as ``position_rad`` /
        ``speed_rad_s`` (``position_m`` / ``speed_m_s`` on a linear axis) and, when the log has one,
        ``reference_rad`` (``reference_m``); ``df.attrs["units"]`` gives each column's unit. The other fields
        (encoder resolution, current-loop bandwidth, ...) are :meth:`to_json`'s."""
        length = "m" if self.linear else "rad"
        effort = ("force_n", "N") if self.linear else ("torque_nm", "N*m")
        meas = (f"speed_{length}_s", f"{length}/s") if self.measured_is_speed else (f"position_{length}", length)
        cols = {"time_s": self.time_s, effort[0]: self.torque_nm, meas[0]: self.measured}
        units = {"time_s": "s", effort[0]: effort[1], meas[0]: meas[1]}
        if self.reference is not None:
            ref = f"reference_{length}" if not self.measured_is_speed else f"reference_{length}_s"
            cols[ref], units[ref] = self.reference, meas[1]
        return dataframe(cols, units)

    def _replace(self, **kw) -> "IdentificationLog":
        d = {f: getattr(self, f) for f in self.__dataclass_fields__}
        d.update(kw)
        return IdentificationLog(**d)

    def to_motor_side(self) -> "IdentificationLog":
        """A linear axis's log seen from the motor: position rad = m * 2 pi / lead, torque N*m = N * lead / (2 pi)
        (a mass M kg becomes M (lead / 2 pi)^2 kg*m^2). Needs lead_m_per_rev."""
        if not self.linear:
            raise ValueError("to_motor_side: the log is already rotary")
        if self.lead_m_per_rev is None:
            raise ValueError("to_motor_side: lead_m_per_rev (m per motor revolution) is not known")
        k = 2 * np.pi / self.lead_m_per_rev
        return self._replace(torque_nm=self.torque_nm / k, measured=self.measured * k,
                             counts_per_rev=self.lead_m_per_rev / self.count_rad, extra=dict(self.extra),
                             reference=None if self.reference is None else self.reference * k, linear=False,
                             count_m=None, lead_m_per_rev=None)

    def split(self, fraction: float) -> tuple["IdentificationLog", "IdentificationLog"]:
        """(first `fraction` of the samples, the rest): e.g. 0.6 for a 60/40 estimation/validation split."""
        if not (0 < fraction < 1):
            raise ValueError(f"split.fraction = {fraction} must be in (0, 1)")
        k = int(round(fraction * len(self)))
        return self._slice(slice(0, k)), self._slice(slice(k, None))

    def _slice(self, s: slice) -> "IdentificationLog":
        extra = {key: (v[s] if isinstance(v, np.ndarray) and v.shape[:1] == (len(self),) else v)
                 for key, v in self.extra.items()}
        return self._replace(torque_nm=self.torque_nm[s], measured=self.measured[s], extra=extra,
                             reference=None if self.reference is None else self.reference[s])

    # ------------------------------------------------------------------------------------------------------------
    @classmethod
    def from_arrays(cls, time_s, command, measured, *, command_unit: str = "N*m", torque_per_volt: float | None = None,
                    measured_unit: str = "rad", counts_per_rev: float = 10000.0, current_bw_hz: float = math.inf,
                    measured_on_load: bool = False, reference=None, count_m: float | None = None,
                    lead_m_per_rev: float | None = None, extra: dict | None = None) -> "IdentificationLog":
        """A log from recorded arrays (e.g. a real machine's trace). time_s: s, increasing, one period apart up to
        +-100 ppm jitter (reported as time_jitter_ppm).

        command
            the drive command held over each sample in command_unit: 'N*m' (or 'mN*m') on a rotary axis, 'N' (or
            'kN', 'mN') on a linear one, or 'V' (converted with torque_per_volt, N*m/V or N/V: the drive gain;
            see :func:`torque_per_volt`).
        measured_unit
            position 'rad', 'deg', 'rev', 'm', 'mm', 'um', 'pulse' (with counts_per_rev, or count_m on a linear axis)
            or speed 'rad/s', 'rpm', 'm/s', 'mm/s', 'pulse/s'. A metre or newton unit makes the log linear.
        reference
            the position reference (closed-loop records), in measured_unit.
        """
        cu = _norm(command_unit)
        if cu not in UNITS or UNITS[cu][0] != "command":
            raise ValueError(f"command_unit = {command_unit!r} must be one of 'N*m', 'mN*m', 'N', 'kN', 'mN', 'V'")
        if cu in ("v", "mv") and (torque_per_volt is None or not (math.isfinite(torque_per_volt)
                                                                  and torque_per_volt > 0)):
            raise ValueError(f"torque_per_volt = {torque_per_volt} must be > 0 (N*m/V or N/V) for a command in volts")
        mu = _norm(measured_unit)
        if mu not in UNITS or UNITS[mu][0] not in ("position", "speed"):
            raise ValueError(f"measured_unit = {measured_unit!r} is not one of "
                             f"{sorted(k for k, v in UNITS.items() if v[0] in ('position', 'speed'))}")
        kinds = {UNITS[cu][1], UNITS[mu][1]} - {None}
        if len(kinds) > 1:
            raise ValueError(f"command_unit {command_unit!r} and measured_unit {measured_unit!r} belong to different "
                             "axis kinds (linear: m, N; rotary: rad, N*m)")
        kind = kinds.pop() if kinds else ("linear" if count_m is not None else "rotary")
        linear = kind == "linear"
        count = count_m if linear else 2 * np.pi / counts_per_rev
        ts, jitter = check_time(time_s, "time_s")
        cf, _ = unit_factor("command", command_unit, "command", kind, gain=torque_per_volt)
        mf, _ = unit_factor("measured", measured_unit, UNITS[mu][0], kind, count_size=count)
        c = finite_column("command", command)
        m = finite_column("measured", measured)
        n = len(np.asarray(time_s))
        if not (len(c) == len(m) == n):
            raise ValueError(f"time_s, command and measured must have the same length (got {n}, {len(c)}, "
                             f"{len(m)})")
        r = None if reference is None else finite_column("reference", reference) * mf
        extra = dict(extra or {})
        if linear and count_m is None and UNITS[mu][0] == "position":
            count_m = detect_count(m * mf)
            if count_m is not None:
                extra["count_m_detected"] = count_m
        return cls(ts, c * cf, m * mf, UNITS[mu][0] == "speed", measured_on_load, counts_per_rev, current_bw_hz,
                   1, extra, r, linear, count_m, lead_m_per_rev, jitter)

    @classmethod
    def from_dataframe(cls, df, *, time: str = "time_s", command: str = "torque_nm", measured: str = "position_rad",
                       reference: str | None = None, units: dict | None = None, command_gain: float | None = None,
                       counts_per_rev: float = 10000.0, count_m: float | None = None,
                       lead_m_per_rev: float | None = None, current_bw_hz: float = math.inf,
                       measured_on_load: bool = False, source: str = "dataframe") -> "IdentificationLog":
        """A log from a pandas DataFrame: `time`, `command`, `measured` (and the optional `reference`) name its
        columns. Each column's unit comes from ``units={column: unit}``, else its header tag (``'qm [mm]'``), else a
        house-name suffix (``time_s``, ``torque_nm``, ``position_pulse``); a column without a known unit, a unit of
        the wrong kind, NaN or a missing column is a ValueError naming the column. command_gain: N/V or N*m/V for
        a column in volts."""
        return cls._from_table(read_dataframe(df, source), source, time, command, measured, reference, units,
                               command_gain, counts_per_rev, count_m, lead_m_per_rev, current_bw_hz, measured_on_load)

    @classmethod
    def from_csv(cls, path: str, *, time: str = "time_s", command: str | None = None, measured: str | None = None,
                 reference: str | None = None, units: dict | None = None, command_gain: float | None = None,
                 counts_per_rev: float = 10000.0, count_m: float | None = None, lead_m_per_rev: float | None = None,
                 current_bw_hz: float = math.inf, measured_on_load: bool = False, torque: str | None = None,
                 measured_unit: str | None = None, command_unit: str | None = None,
                 torque_per_volt: float | None = None) -> "IdentificationLog":
        """A log from a CSV file with a header row (pandas), the same format as ``servobench identify --log``.

        Columns as in :meth:`from_dataframe`; `command` defaults to the first of torque_nm, force_n, volts present
        and `measured` to the first of position_pulse, position_rad, position_m, speed_rad_s, speed_pulse_s,
        speed_m_s; `reference` to 'reference' when present. The older spelling (torque=, measured_unit=,
        command_unit=, torque_per_volt=) still works: it sets the units of the named columns."""
        cols = read_csv(path)
        commands = ("torque_nm", "force_n", "volts")
        measures = ("position_pulse", "position_rad", "position_m", "speed_rad_s", "speed_pulse_s", "speed_m_s")
        command = command or torque or next((c for c in commands if c in cols), None)
        measured = measured or next((c for c in measures if c in cols), None)
        if command is None:
            raise ValueError(f"{path}: no command column: one of {', '.join(commands)}, or name it (command=...) "
                             f"(columns: {', '.join(cols)})")
        if measured is None:
            raise ValueError(f"{path}: no measured column: one of {', '.join(measures)}, or name it (measured=...) "
                             f"(columns: {', '.join(cols)})")
        if reference is None and "reference" in cols:
            reference = "reference"
        units = dict(units or {})
        if torque is not None or measured_unit is not None or command_unit is not None:
            units.setdefault(time, "s")  # the older spelling's time column was in seconds by definition
        if measured_unit is not None:
            units.setdefault(measured, measured_unit)
        if command_unit is not None:
            units.setdefault(command, command_unit)
        gain = command_gain if command_gain is not None else torque_per_volt
        return cls._from_table(cols, path, time, command, measured, reference, units, gain, counts_per_rev, count_m,
                               lead_m_per_rev, current_bw_hz, measured_on_load)

    @classmethod
    def from_mat(cls, path: str, *, time: str = "t", command: str = "vir", measured: str = "qm",
                 reference: str | None = "qg", units: dict | None = None, command_gain: float | str | None = None,
                 counts_per_rev: float = 10000.0, count_m: float | None = None, lead_m_per_rev: float | None = None,
                 current_bw_hz: float = math.inf, measured_on_load: bool = False) -> "IdentificationLog":
        """A log from a MATLAB .mat file (scipy.io.loadmat): `time`, `command`, `measured`, `reference` name its
        variables (the defaults are the EMPS benchmark's), `units` gives their units (a .mat file carries none:
        every mapped variable needs one), `command_gain` is a number or the name of a scalar variable (N/V, e.g.
        'gtau'). The file's other scalars (loop gains, ...) are kept in ``log.extra``; reference=None when the
        record has none."""
        cols = read_mat(path)
        if isinstance(command_gain, str):
            if command_gain not in cols:
                raise ValueError(f"{path}: no variable {command_gain!r} for command_gain (variables: "
                                 f"{', '.join(cols)})")
            command_gain = float(np.asarray(cols[command_gain][0], float).ravel()[0])
        log = cls._from_table(cols, path, time, command, measured, reference, units, command_gain, counts_per_rev,
                              count_m, lead_m_per_rev, current_bw_hz, measured_on_load)
        for k, (v, _u) in cols.items():
            a = np.asarray(v)
            if a.size == 1 and np.issubdtype(a.dtype, np.number):
                log.extra[k] = float(a.ravel()[0])
        return log

    @classmethod
    def _from_table(cls, cols, source, time, command, measured, reference, units, gain, counts_per_rev, count_m,
                    lead_m_per_rev, current_bw_hz, measured_on_load):
        units = dict(units or {})
        wanted = [time, command, measured] + ([reference] if reference else [])
        for want in wanted:
            if want not in cols:
                raise ValueError(f"{source}: no column {want!r} (columns: {', '.join(cols)})")
        unknown = set(units) - set(cols)
        if unknown:
            raise ValueError(f"{source}: units= names column(s) {sorted(unknown)} that the record does not have")
        try:
            u = {c: column_unit(c, cols[c][1], units) for c in wanted}
            mq = UNITS.get(_norm(u[measured]), ("?",))[0]
            if mq not in ("position", "speed"):
                unit_factor(measured, u[measured], "position", None)  # raises naming the column
            cq = UNITS.get(_norm(u[command]), ("?",))[0]
            if cq != "command":
                unit_factor(command, u[command], "command", None)
            ck = UNITS[_norm(u[command])][1]
            mk = UNITS[_norm(u[measured])][1]
            if ck and mk and ck != mk:
                raise ValueError(f"column {measured!r}: unit {u[measured]!r} is a {mk} unit, but the axis is {ck} "
                                 f"(column {command!r} is in {u[command]})")
            tf, _ = unit_factor(time, u[time], "time", None)
            t = finite_column(time, cols[time][0]) * tf
            vals = {c: finite_column(c, cols[c][0]) for c in wanted if c != time}
        except ValueError as e:
            raise ValueError(f"{source}: {e}") from None
        try:
            log = cls.from_arrays(t, vals[command], vals[measured], command_unit=u[command], torque_per_volt=gain,
                                  measured_unit=u[measured], counts_per_rev=counts_per_rev,
                                  current_bw_hz=current_bw_hz, measured_on_load=measured_on_load, count_m=count_m,
                                  lead_m_per_rev=lead_m_per_rev)
        except ValueError as e:
            msg = str(e)
            for role, col in (("command", command), ("measured", measured), ("time_s", time)):
                msg = msg.replace(f"column {role!r}", f"column {col!r}").replace(f"{role}[", f"{col}[")
                msg = msg.replace(f"{role} is not", f"{col} is not").replace(f"{role} has a gap", f"{col} has a gap")
            raise ValueError(f"{source}: {msg}") from None
        if reference:
            rq = UNITS.get(_norm(u[reference]), ("?",))[0]
            if rq != "position":
                raise ValueError(f"{source}: column {reference!r}: the reference must be a position (unit "
                                 f"{u[reference]!r})")
            try:
                rf, _ = unit_factor(reference, u[reference], "position", "linear" if log.linear else "rotary",
                                    count_size=log.count_rad)
            except ValueError as e:
                raise ValueError(f"{source}: {e}") from None
            object.__setattr__(log, "reference", vals[reference] * rf)
        log.extra["source"] = source
        log.extra["columns"] = dict(u)
        return log

    def to_csv(self, path: str) -> None:
        """Writes the log in the reader's format: time_s, torque_nm (force_n on a linear axis) and position_rad /
        speed_rad_s (position_m / speed_m_s), unit-tagged headers, plus reference when the log has one."""
        import pandas as pd

        lin = self.linear
        eff = "force_n [N]" if lin else "torque_nm [N*m]"
        if self.measured_is_speed:
            meas = "speed_m_s [m/s]" if lin else "speed_rad_s [rad/s]"
        else:
            meas = "position_m [m]" if lin else "position_rad [rad]"
        d = {"time_s [s]": self.time_s, eff: self.torque_nm, meas: self.measured}
        if self.reference is not None:
            d["reference [m]" if lin else "reference [rad]"] = self.reference
        pd.DataFrame(d).to_csv(path, index=False, float_format="%.17g")
