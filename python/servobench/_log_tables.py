"""The tables an identification log is read from: unit tags and SI factors, the column checks (finite values,
real time vectors, the count size of a position), the motor side of a linear axis's figures, and the readers of a
CSV file, a pandas DataFrame and a MATLAB ``.mat`` file (the units are listed in :mod:`servobench.idlog`). Defined
here, published by :mod:`servobench.idlog` (decision OR2); the log type is there.
"""

from __future__ import annotations

import math
import re

import numpy as np



#: Steps of a real time vector may differ from the median step by this much (parts per million) and be accepted.
MAX_JITTER_PPM = 100.0

# a linear quantity's unit -> (its motor-side unit, power of lead / 2 pi that converts it)
_MOTOR_SIDE = {"kg": ("kg*m^2", 2), "N*s/m": ("N*m*s/rad", 2), "N": ("N*m", 1), "m": ("rad", -1),
               "m/s": ("rad/s", -1)}


def motor_side(value: float, unit: str, lead_m_per_rev: float) -> tuple[float, str]:
    """(value, unit) of a linear-axis quantity seen from the motor through a screw lead / gear ratio of
    lead_m_per_rev (m of travel per motor revolution, k = lead / 2 pi): mass kg -> kg*m^2 (x k^2), viscous N*s/m ->
    N*m*s/rad (x k^2), force N -> N*m (x k), position m -> rad and speed m/s -> rad/s (/ k). Other units unchanged."""
    if unit not in _MOTOR_SIDE:
        return value, unit
    to, power = _MOTOR_SIDE[unit]
    return value * (lead_m_per_rev / (2 * math.pi)) ** power, to


def motor_side_line(items, lead_m_per_rev: float | None) -> str | None:
    """'motor side (lead L mm/rev): name = value unit, ...' for (name, value, linear unit) items, or None without a
    lead."""
    if lead_m_per_rev is None:
        return None
    parts = []
    for name, value, unit in items:
        v, u = motor_side(value, unit, lead_m_per_rev)
        parts.append(f"{name} = {v:.6g} {u}")
    return f"motor side (lead {1e3 * lead_m_per_rev:.6g} mm/rev): " + ", ".join(parts)

# unit -> (quantity, axis kind or None for both, SI factor; 'count' = times the count size)
UNITS = {
    "s": ("time", None, 1.0), "ms": ("time", None, 1e-3), "us": ("time", None, 1e-6),
    "m": ("position", "linear", 1.0), "mm": ("position", "linear", 1e-3), "um": ("position", "linear", 1e-6),
    "rad": ("position", "rotary", 1.0), "deg": ("position", "rotary", math.pi / 180),
    "rev": ("position", "rotary", 2 * math.pi),
    "pulse": ("position", None, "count"), "count": ("position", None, "count"), "counts": ("position", None, "count"),
    "m/s": ("speed", "linear", 1.0), "mm/s": ("speed", "linear", 1e-3),
    "rad/s": ("speed", "rotary", 1.0), "deg/s": ("speed", "rotary", math.pi / 180),
    "rpm": ("speed", "rotary", 2 * math.pi / 60), "rev/s": ("speed", "rotary", 2 * math.pi),
    "pulse/s": ("speed", None, "count"), "count/s": ("speed", None, "count"),
    "n": ("command", "linear", 1.0), "kn": ("command", "linear", 1e3), "mn": ("command", "linear", 1e-3),
    "n*m": ("command", "rotary", 1.0), "nm": ("command", "rotary", 1.0), "n.m": ("command", "rotary", 1.0),
    "mn*m": ("command", "rotary", 1e-3), "mnm": ("command", "rotary", 1e-3),
    "v": ("command", None, "volt"), "mv": ("command", None, "volt_milli"),
}

# house column names (time_s, torque_nm, position_rad, ...) -> unit
_SUFFIX = {"time_s": "s", "torque_nm": "N*m", "force_n": "N", "volts": "V", "voltage_v": "V",
           "position_rad": "rad", "position_pulse": "pulse", "position_m": "m", "position_mm": "mm",
           "speed_rad_s": "rad/s", "speed_pulse_s": "pulse/s", "speed_m_s": "m/s", "reference_rad": "rad",
           "reference_m": "m", "reference_pulse": "pulse"}

_TAG = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*\[(?P<unit>[^\[\]]*)\]\s*$")


def _norm(unit: str) -> str:
    return str(unit).strip().replace("·", "*").replace("µ", "u").replace(" ", "").lower()


def parse_header(header: str) -> tuple[str, str | None]:
    """('position', 'mm') from 'position [mm]'; (name, None) without a tag. A header with unbalanced brackets is an
    error naming it."""
    h = str(header)
    m = _TAG.match(h)
    if m:
        return m["name"], m["unit"].strip()
    if "[" in h or "]" in h:
        raise ValueError(f"column {h!r}: malformed unit tag (expected 'name [unit]')")
    return h.strip(), None


def unit_factor(column: str, unit: str, quantity: str, kind: str | None, *, count_size: float | None = None,
                gain: float | None = None) -> tuple[float, str | None]:
    """(SI factor, axis kind) of `unit` for `column` holding `quantity` ('time', 'position', 'speed', 'command') on
    an axis of `kind` ('linear', 'rotary' or None = either). count_size: one count in m or rad (pulse units);
    gain: the drive gain, N/V or N*m/V (volt units). ValueError naming the column otherwise."""
    u = _norm(unit)
    if u not in UNITS:
        raise ValueError(f"column {column!r}: unknown unit {unit!r} (known {quantity} units: "
                         f"{', '.join(k for k, v in UNITS.items() if v[0] == quantity)})")
    q, k, f = UNITS[u]
    if q != quantity:
        raise ValueError(f"column {column!r}: unit {unit!r} is a {q} unit, the column must hold a {quantity}")
    if kind is not None and k is not None and k != kind:
        raise ValueError(f"column {column!r}: unit {unit!r} is a {k} unit, but the axis is {kind}")
    if f == "count":
        if count_size is None or not (math.isfinite(count_size) and count_size > 0):
            raise ValueError(f"column {column!r} is in {unit}: give the count size (counts_per_rev for a rotary "
                             f"axis, count_m for a linear one)")
        f = count_size
    elif f in ("volt", "volt_milli"):
        if gain is None or not (math.isfinite(gain) and gain > 0):
            raise ValueError(f"column {column!r} is in {unit}: give the drive gain (command_gain, N/V or N*m/V > 0)")
        f = gain * (1e-3 if f == "volt_milli" else 1.0)
    return float(f), (k or kind)


def column_unit(column: str, header_unit: str | None, units: dict) -> str:
    """The unit of `column`: units[column], else its header tag, else its house-name suffix; a ValueError naming
    the column when none is known."""
    if column in units:
        return units[column]
    if header_unit is not None:
        return header_unit
    if column in _SUFFIX:
        return _SUFFIX[column]
    raise ValueError(f"column {column!r} has no unit: tag its header ('{column} [unit]') or pass "
                     f"units={{'{column}': ...}}")


def check_time(t, name: str = "time") -> tuple[float, float]:
    """(sample period s, largest jitter ppm) of a real time vector; ValueError naming the first bad sample for
    non-finite, non-monotonic, gapped or irregular time."""
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or len(t) < 3:
        raise ValueError(f"{name}: needs a 1-D time vector of at least 3 samples (got shape {t.shape})")
    bad = np.flatnonzero(~np.isfinite(t))
    if len(bad):
        raise ValueError(f"{name}[{bad[0]}] = {t[bad[0]]} is not a finite number")
    dt = np.diff(t)
    nonmono = np.flatnonzero(dt <= 0)
    if len(nonmono):
        i = int(nonmono[0]) + 1
        raise ValueError(f"{name} is not increasing at sample {i}: {name}[{i}] = {float(t[i])!r} <= {name}[{i - 1}] = "
                         f"{float(t[i - 1])!r}")
    ts = float(np.median(dt))
    gaps = np.flatnonzero(dt > 1.5 * ts)
    if len(gaps):
        i = int(gaps[0]) + 1
        raise ValueError(f"{name} has a gap at sample {i}: step {dt[i - 1]:.6g} s is {dt[i - 1] / ts:.3g} sample "
                         f"periods ({ts:.6g} s); split the record or fill the gap")
    ppm = np.abs(dt / ts - 1.0) * 1e6
    worst = int(np.argmax(ppm))
    if ppm[worst] > MAX_JITTER_PPM:
        raise ValueError(f"{name} is not uniformly sampled at sample {worst + 1}: step {dt[worst]:.6g} s differs "
                         f"from the period {ts:.6g} s by {ppm[worst]:.4g} ppm (> {MAX_JITTER_PPM:g} ppm jitter); "
                         "resample it first")
    return ts, float(ppm[worst])


def finite_column(name: str, values) -> np.ndarray:
    """values as a 1-D float array; ValueError naming the column and the first non-numeric or non-finite sample."""
    try:
        a = np.asarray(values, dtype=float).ravel()
    except (TypeError, ValueError):
        raise ValueError(f"column {name!r} holds values that are not numbers") from None
    bad = np.flatnonzero(~np.isfinite(a))
    if len(bad):
        raise ValueError(f"{name}[{bad[0]}] = {a[bad[0]]} is not a finite number (column {name!r}, {len(bad)} such "
                         "samples)")
    return a


def detect_count(position) -> float | None:
    """The encoder's count (m or rad) of a quantised position record: its smallest non-zero step, when at least
    99 % of the steps are whole multiples of it (within 1 %); None otherwise."""
    d = np.abs(np.diff(np.asarray(position, float)))
    d = d[d > 0]
    if len(d) < 10:
        return None
    q = float(np.min(d))
    k = d / q
    if np.mean(np.abs(k - np.round(k)) < 0.01) >= 0.99:
        return q
    return None


def read_csv(path: str) -> dict:
    """{column name without tag: (values, header unit or None)} of a CSV file with a header row, read by pandas;
    ValueError naming the file (and the column) on bad input."""
    import pandas as pd

    try:
        df = pd.read_csv(path, skipinitialspace=True, comment="#")
    except FileNotFoundError:
        raise ValueError(f"{path}: no such file") from None
    except pd.errors.EmptyDataError:
        raise ValueError(f"{path}: empty file (expected a header row and data)") from None
    except (pd.errors.ParserError, UnicodeDecodeError) as e:
        raise ValueError(f"{path}: not a readable CSV ({e})") from None
    for col in df.columns:
        if not pd.api.types.is_numeric_dtype(df[col]):  # a cell that is not a number: name its line (header: 1)
            num = pd.to_numeric(df[col], errors="coerce")
            bad = np.flatnonzero(num.isna().to_numpy() & df[col].notna().to_numpy())
            if len(bad):
                raise ValueError(f"{path}: line {bad[0] + 2}, column {parse_header(col)[0]}: "
                                 f"'{df[col].iloc[bad[0]]}' is not a number")
    return read_dataframe(df, source=path)


def read_dataframe(df, source: str = "dataframe") -> dict:
    """{name: (values, header unit or None)} of a pandas DataFrame whose headers may carry '[unit]' tags."""
    out = {}
    if len(df) == 0:
        raise ValueError(f"{source}: no data rows")
    for col in df.columns:
        name, unit = parse_header(col)
        if name in out:
            raise ValueError(f"{source}: column {name!r} appears twice")
        out[name] = (df[col].to_numpy(), unit)
    return out


def read_mat(path: str) -> dict:
    """{variable: (values, None)} of a MATLAB .mat file (scipy.io.loadmat)."""
    from scipy import io

    try:
        d = io.loadmat(path, squeeze_me=True)
    except FileNotFoundError:
        raise ValueError(f"{path}: no such file") from None
    except (ValueError, TypeError, OSError) as e:
        raise ValueError(f"{path}: not a readable MATLAB file ({e})") from None
    return {k: (v, None) for k, v in d.items() if not k.startswith("__")}
