"""The parser of the command line (options read from the C++ structs where they are described) and main()."""

from __future__ import annotations

import argparse
import sys

from .. import _core
from ._bode import _KIND, cmd_bode
from ._common import EXIT_FAILED, EXIT_OK, EXIT_USAGE, UsageError, WorkFailed
from ._demo import cmd_demo
from ._identify import LOG_COLUMNS, cmd_identify
from ._simulate import cmd_simulate
from ._tune import cmd_tune


# ----------------------------------------------------------------------------------------------------------------
# The parser
# ----------------------------------------------------------------------------------------------------------------
class _Formatter(argparse.ArgumentDefaultsHelpFormatter, argparse.RawDescriptionHelpFormatter):
    pass


def _described(group, flag: str, options_class, name: str, help_prefix: str = ""):
    """An option whose default, type, unit and meaning are those of a C++ options struct (its describe() table,
    read through the binding; decision OQ4): nothing retyped here."""
    from .. import _options

    f = next(f for f in _options.option_fields(options_class) if f.name == name)
    unit = f" [{f.unit}]" if f.unit else ""
    text = (help_prefix + f.doc + unit).replace("%", "%%")  # argparse formats help with %
    group.add_argument(flag, type=int if f.type == "int" else float, default=f.default, help=text)


def build_parser() -> argparse.ArgumentParser:
    from .. import __version__

    common = argparse.ArgumentParser(add_help=False)
    g = common.add_argument_group("output")
    g.add_argument("--out", default="out", metavar="DIR", help="folder for the files written")
    g.add_argument("--format", choices=["png", "svg"], default="png", help="plot file format")
    g.add_argument("--quiet", "-q", action="store_true", help="print only the files written; no progress bars")
    g.add_argument("--progress", action="store_true",
                   help="progress bars on stderr even when it is not a terminal (default: only on a terminal)")

    p = argparse.ArgumentParser(
        prog="servobench", formatter_class=_Formatter,
        description="servobench: simulate, measure, tune and identify a servo axis described in a TOML/JSON file.",
        epilog="Each command's --help lists its options with units. Exit codes: 0 done, 1 the work failed, "
               "2 usage error or bad input file. Axis files: docs/cli.md; examples in examples/axes/.")
    p.add_argument("--version", action="version", version=f"servobench {__version__}")
    sub = p.add_subparsers(dest="command", metavar="<command>")

    s = sub.add_parser("simulate", parents=[common], formatter_class=_Formatter,
                       help="run a point-to-point move: trace (CSV), metrics (JSON), response plot",
                       description="Runs a point-to-point move on the axis and writes <stem>_trace.csv (every signal "
                                   "per tick, units in the header), <stem>_metrics.json (rise time, overshoot, "
                                   "settling time, peak following error) and <stem>_response.<format>.")
    s.add_argument("axis", metavar="AXIS", help="axis file (.toml or .json)")
    s.add_argument("--move", choices=["trapezoid", "s-curve"], default="trapezoid",
                   help="profile: trapezoid (servobench.trapezoid_move) or s-curve (the GT card's GT_PrflS)")
    s.add_argument("--distance-pulse", type=float, default=10000.0, help="move length, pulse (signed)")
    s.add_argument("--vel", type=float, default=20.0, help="cruise velocity, pulse/tick")
    s.add_argument("--acc", type=float, default=0.1, help="acceleration, pulse/tick^2 (s-curve: the maximum, < 0.5)")
    s.add_argument("--jerk", type=float, default=0.001, help="s-curve jerk, pulse/tick^3 (0 < jerk < 0.5)")
    s.add_argument("--dwell-before", type=int, default=50, help="ticks at rest before the move")
    s.add_argument("--dwell-after", type=int, default=1000, help="ticks at rest after the move")
    s.add_argument("--ticks", type=int, default=None,
                   help="run exactly this many ticks (the end held, or the move cut); default: the move + dwells")
    s.add_argument("--settle-band-pulse", type=float, default=5.0, help="in-position band for the settling time, pulse")
    s.set_defaults(func=cmd_simulate)

    b = sub.add_parser("bode", parents=[common], formatter_class=_Formatter,
                       help="stepped-sine Bode sweep (the ADLINK Bode tool): response CSV/JSON, margins, plot",
                       description="Measures the loop with the ADLINK Bode tool's stepped sine (defaults = the "
                                   "manual's example, L2023/L2035) and writes <stem>_bode.csv (gain dB and phase deg "
                                   "of plant Y/U, open loop Y/E, closed loop Y/R per frequency), <stem>_bode.json "
                                   "(margins measured and analytic, status) and <stem>_bode.<format> (measured dots "
                                   "on the analytic model).")
    b.add_argument("axis", metavar="AXIS", help="axis file (.toml or .json)")
    b.add_argument("--kind", choices=list(_KIND), default="open",
                   help="response plotted: plant Y/U (pulse/count), open loop Y/E, closed loop Y/R")
    _described(b, "--start-hz", _core.SineSweepOptions, "start_hz")
    _described(b, "--end-hz", _core.SineSweepOptions, "end_hz")
    _described(b, "--points", _core.SineSweepOptions, "points")
    b.add_argument("--amplitude-pulse", type=float, default=None,
                   help="sine amplitude added to the command, pulse (the manual's example: 300); default: chosen per "
                        "point to keep the DAC and the drive out of saturation and above quantisation")
    _described(b, "--update-s", _core.SineSweepOptions, "update_s")
    _described(b, "--deviation-limit-pulse", _core.SineSweepOptions, "deviation_limit_pulse")
    b.add_argument("--feedforward", action="store_true", help="keep the feed-forward in the loop (no margins then)")
    b.add_argument("--analytic", action="store_true",
                   help="compute the analytic response of the linear model instead of measuring (instant)")
    b.set_defaults(func=cmd_bode)

    t = sub.add_parser("tune", parents=[common], formatter_class=_Formatter,
                       help="relay or model-based auto-tuning: tuned axis file, report, step and Bode before/after",
                       description="Tunes the position loop and writes <stem>_tuned.<toml|json> (the axis file with "
                                   "the new gains, in the input's format), <stem>_tune.json (gains, designed and "
                                   "measured margins, step metrics), <stem>_tune_step.<format> (step response before "
                                   "and after) and <stem>_tune_bode.<format> (open loop before and after).")
    t.add_argument("axis", metavar="AXIS", help="axis file (.toml or .json)")
    t.add_argument("--method", choices=["model", "relay"], default="model",
                   help="model: design from the axis's analytic plant (servobench.model_based_tune); relay: the "
                        "ADLINK relay experiment (needs a velocity-mode drive)")
    _described(t, "--phase-margin-deg", _core.ModelTuneOptions, "phase_margin_deg")
    m = t.add_argument_group("model-based tuning")
    _described(m, "--alpha", _core.ModelTuneOptions, "alpha")
    _described(m, "--min-gain-margin-db", _core.ModelTuneOptions, "min_gain_margin_db")
    _described(m, "--max-ms", _core.ModelTuneOptions, "max_ms")
    m.add_argument("--no-notch", action="store_true", help="do not try a notch at the plant's resonance")
    r = t.add_argument_group("relay tuning (ADLINK manual L1842-1847 defaults)")
    _described(r, "--amplitude-v", _core.RelayTuneOptions, "amplitude_v")
    _described(r, "--hysteresis-pulse", _core.RelayTuneOptions, "hysteresis_pulse")
    _described(r, "--data-length", _core.RelayTuneOptions, "data_length")
    r.add_argument("--rule", choices=["phase_margin", "ziegler_nichols", "tyreus_luyben"], default="phase_margin",
                   help="gains from the experiment by this rule")
    v = t.add_argument_group("verification")
    v.add_argument("--step-pulse", type=float, default=100.0, help="step for the before/after response, pulse")
    v.add_argument("--step-ticks", type=int, default=1000, help="length of the step runs, ticks")
    v.add_argument("--start-hz", type=float, default=10.0, help="verification sweep and Bode plot from, Hz")
    v.add_argument("--end-hz", type=float, default=1000.0, help="... to, Hz (capped at 0.9 Nyquist)")
    v.add_argument("--points", type=int, default=40, help="verification sweep points")
    v.add_argument("--amplitude-pulse", type=float, default=None,
                   help="verification sweep amplitude, pulse (default: chosen per point, out of saturation)")
    v.add_argument("--force", action="store_true",
                   help="write the tuned axis even when the tuned loop fails its check (stability, PM within 5 deg of "
                        "the target, gain-margin floor; model and verification sweep)")
    v.add_argument("--no-sweep", action="store_true", help="skip the measured sweep of the tuned loop")
    t.set_defaults(func=cmd_tune)

    i = sub.add_parser("identify", parents=[common], formatter_class=_Formatter,
                       help="fit a rigid or two-mass plant (Ceres) to the standard experiment or a CSV log",
                       description="Identifies the mechanics: `identify AXIS` runs the standard experiment on the "
                                   "described axis as a digital twin (servobench.run_experiment) and fits it; "
                                   "`identify --log LOG.csv` fits a recorded log. Writes <stem>_identified.json "
                                   "(estimates with standard errors), <stem>_identify_fit.<format> (fit and residual), "
                                   "<stem>_identified.<toml|json> (the axis file with the identified plant) and, for "
                                   "the twin, <stem>_identify_log.csv.\n\nLog CSV columns (header row; a ' [unit]' "
                                   "tag gives a column's unit -- mm, deg, mN*m, ... are converted, an unknown unit is "
                                   "an error; a .mat file needs --unit for each column):\n" + "\n".join(f"  {k:15s} {v}" for k, v in LOG_COLUMNS.items()))
    i.add_argument("axis", metavar="AXIS", nargs="?", default=None,
                   help="axis file: the twin to run the experiment on; with --log: drive, encoder and starting values")
    i.add_argument("--log", metavar="LOG.csv", default=None, help="fit this log instead of running the experiment")
    i.add_argument("--model", choices=["rigid", "two-mass", "two_mass"], default=None,
                   help="plant model (default: the axis file's plant type, else rigid)")
    i.add_argument("--guess", nargs="+", metavar="NAME=VALUE", action="extend",
                   help="starting value (SI) of a parameter to estimate; default: the axis file's non-zero plant "
                        "values")
    i.add_argument("--fixed", nargs="+", metavar="NAME", action="extend", help="parameters held at their guess")
    i.add_argument("--duration-s", type=float, default=5.0, help="experiment length, s")
    i.add_argument("--amplitude-v", type=float, default=0.1, help="PRBS injection amplitude at the DAC, V")
    i.add_argument("--seed", type=int, default=0, help="PRBS seed")
    i.add_argument("--torque-per-volt", "--command-gain", dest="torque_per_volt", type=float, default=None,
                   help="drive gain, N*m/V (N/V on a linear axis), for a command column in volts")
    i.add_argument("--time", dest="time_column", default=None, help="the log's time column (default time_s; a .mat file: t)")
    i.add_argument("--command", dest="command_column", default=None, help="the log's command column (default: torque_nm, force_n or volts)")
    i.add_argument("--measured", dest="measured_column", default=None, help="the log's measured column (default: position_pulse, "
                                                    "position_rad, position_m, speed_rad_s, ...)")
    i.add_argument("--reference", dest="reference_column", default=None, help="the log's position reference column (closed-loop records)")
    i.add_argument("--unit", nargs="+", metavar="COLUMN=UNIT", action="extend",
                   help="a column's unit when its header has no [unit] tag, e.g. qm=m vir=V")
    i.add_argument("--dynamics-hz", type=float, default=None,
                   help="the closed loop's dynamics frequency, Hz, for the IDIM start (default: from the log's "
                        "reference)")
    i.add_argument("--count-m", type=float, default=None, help="one encoder count, m (linear axes; default: "
                                                               "detected from the position's steps)")
    i.add_argument("--counts-per-rev", type=float, default=None, help="encoder counts/rev for pulse columns "
                                                                        "(default: the axis file's, else 10000)")
    i.add_argument("--current-bw-hz", type=float, default=None,
                   help="drive current-loop bandwidth, Hz (default: the axis file's, else ideal)")
    i.set_defaults(func=cmd_identify)

    d = sub.add_parser("demo", formatter_class=_Formatter,
                       help="the README's quick start: move, Bode sweep, identification and tuning on the reference axis",
                       description="Simulates a move on the reference axis (servobench.demo_axis), measures its loop, "
                                   "identifies its plant, tunes from the model and writes demo_response_<law>.png, "
                                   "demo_bode_<law>.png and demo_bode_tuned_<law>.png.")
    d.add_argument("--law", choices=["gt", "aps"], default="gt", help="servo law")
    d.add_argument("--out", default="out", metavar="DIR", help="folder for the plots")
    d.set_defaults(func=cmd_demo)
    return p


def main(argv=None) -> int:
    """Runs the command line; returns the exit code (0 done, 1 the work failed, 2 usage error or bad input)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    if not argv:
        parser.print_help()
        return EXIT_OK
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:  # --help, --version, usage errors (argparse printed them)
        return e.code if isinstance(e.code, int) else EXIT_USAGE
    if args.command is None:
        parser.print_help()
        return EXIT_USAGE
    from ..axisfile import AxisFileError

    try:
        return args.func(args)
    except (AxisFileError, UsageError) as e:
        print(f"servobench: error: {e}", file=sys.stderr)
        return EXIT_USAGE
    except WorkFailed as e:
        print(f"servobench {args.command}: failed: {e}", file=sys.stderr)
        return EXIT_FAILED
    except (OSError, ValueError, RuntimeError) as e:  # an output that cannot be written, the library refusing
        print(f"servobench {args.command}: failed: {e}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        print(f"servobench {args.command}: interrupted", file=sys.stderr)
        return 130
