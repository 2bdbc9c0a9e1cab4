"""servobench: a simulator of industrial motion controllers and a servo-tuning workbench.

The C++ core steps one servo tick at a time (command -> servo law -> filters -> DAC -> drive -> plant ->
encoder) with the vendor manuals' exact discrete laws; this package is its Python face.

Units: controller side in pulse, pulse/tick, pulse/tick^2 and DAC counts (32767 counts = 10 V); the drive
and the plant in SI (V, A, N*m, kg*m^2, rad, rad/s); time in s.

Quick use::

    import servobench as sb
    axis = sb.demo_axis()
    move = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1,
                             dwell_after=1000)
    run = axis.run(move)
    print(sb.move_metrics(run))
"""

from ._core import (
    AdlinkBiquad,
    ApsServoLaw,
    Dac,
    Encoder,
    FloatBiquad,
    GtServoLaw,
    LtiPlant,
    RigidPlant,
    ServoPositionDrive,
    StepperDrive,
    Switches,
    TorqueDrive,
    TwoMassPlant,
    VelocityDrive,
)
from .axis import Axis, AxisRun, DEFAULT_SIGNALS, SIGNALS, SIGNAL_UNITS, controller_signature
from .trajectory import Trajectory, trapezoid_move
from .metrics import MoveMetrics, move_metrics
from .examples import demo_axis
from . import design, plot
from . import axisfile
from .axisfile import AxisFileError, load_axis, save_axis  # axis description files (TOML/JSON), issue 11.2
from . import frequency
from . import autotune
from . import identify
from .identify import IdentificationError, IdentificationLog, IdentifiedPlant, fit_frequency, fit_time, run_experiment
from . import experiment, frequency_fit
from .frequency_fit import MechanicsIO
from . import idim, idlog, oefit, validation
from .idim import IdimResult, idim_iv, idim_ls
from .validation import CascadePD, RigidModel, ValidationResult, simulate_rigid, validate
from .identify_workflow import RigidIdentification, identify_rigid
from .autotune import ModelTuneResult, RelayTuneResult, model_based_tune, relay_autotune
from .frequency import FrequencyResponse, Margins, analytic_response, broadband_response, sine_sweep
from . import interop  # python-control both ways, LtiPlant.from_control (issue 23.3-23.4)
from .interop import lti_plant, to_control
from . import motion
from . import homing
from . import gearing
from .gearing import gear_trajectory
from .homing import AdlinkHome, AdlinkJog, GtHome, HomingResult, LoopRun, MotionLoop, home
from . import pvt
from .pvt import (
    FollowEx,
    FollowExSetup,
    FollowSegment,
    PvtAxis,
    PvtCurve,
    PvtTables,
    ReturnCode,
    follow_cam,
    follow_trajectory,
    pvt_complete_calculate,
    pvt_continuous_calculate,
    pvt_percent_calculate,
    pvt_start,
    pvt_table,
    pvt_table_complete,
    pvt_table_continuous,
    pvt_table_continuous_ex,
    pvt_table_ex,
    pvt_table_percent,
    pvt_trajectory,
)
from . import paths
from .paths import (
    CoordSystem,
    LookAheadParams,
    PathGenerator,
    PathGeometryError,
    PathRun,
    PathSegment,
    PathSetup,
    plan_polyline_lookahead,
    run_path,
    AdlinkInterpolator,
    AdlinkInterpSetup,
    AdlinkRun,
    BlendMode,
    CrdFifoPair,
    GeLookAhead,
    GeLookAheadParams,
    run_adlink,
)
from . import batch
from .batch import BatchResult, monte_carlo, sample_spread, simulate_many  # many plants at once (issue 22)
from .tune_robust import RobustTuneResult, tune_robust  # tuning for the worst plant of a spread (issue 22.3)
from . import card
from .card import CARD_EVENTS, Card, CardCommandRefused, CardLimits, CardRun, events_named
from .card import SAMPLE_SIGNALS, FiredEvent, ScopeData  # the card's scope and event callbacks (issue 10.3)
from . import card_clock
from .card_clock import CardClock, ClockOptions, ClockStats  # time modes: step, program, realtime (issue 25.1)
from . import dialects
from .motion import (
    AdlinkPtp,
    ElectronicGear,
    GtGear,
    GeJog,
    GeSCurve,
    GeTCurve,
    GtJog,
    GtSCurve,
    GtTCurve,
    MotionCommandRefused,
    ProfileGenerator,
    jog_trajectory,
    move_trajectory,
)
from . import widgets  # the Jupyter tuning panel, sb.widgets.tuner(axis) (issue 23.2; needs ipywidgets)

from ._public import limit_dir_to_all as _limit_dir_to_all

__version__ = "0.1.0"

__all__ = [
    "batch",
    "BatchResult",
    "monte_carlo",
    "tune_robust",
    "RobustTuneResult",
    "sample_spread",
    "simulate_many",
    "controller_signature",
    "CARD_EVENTS",
    "Card",
    "CardCommandRefused",
    "CardLimits",
    "CardRun",
    "CardClock",
    "ClockOptions",
    "ClockStats",
    "card_clock",
    "FiredEvent",
    "SAMPLE_SIGNALS",
    "ScopeData",
    "card",
    "dialects",
    "events_named",
    "AdlinkBiquad",
    "AxisFileError",
    "axisfile",
    "load_axis",
    "save_axis",
    "AdlinkHome",
    "AdlinkJog",
    "AdlinkPtp",
    "FrequencyResponse",
    "RelayTuneResult",
    "ModelTuneResult",
    "autotune",
    "identify",
    "IdentificationError",
    "IdentificationLog",
    "IdentifiedPlant",
    "fit_frequency",
    "MechanicsIO",
    "experiment",
    "frequency_fit",
    "fit_time",
    "run_experiment",
    "idim",
    "idim_ls",
    "idim_iv",
    "IdimResult",
    "validation",
    "idlog",
    "oefit",
    "validate",
    "ValidationResult",
    "RigidModel",
    "CascadePD",
    "simulate_rigid",
    "identify_rigid",
    "RigidIdentification",
    "relay_autotune",
    "model_based_tune",
    "Margins",
    "analytic_response",
    "broadband_response",
    "frequency",
    "sine_sweep",
    "GtHome",
    "HomingResult",
    "LoopRun",
    "MotionLoop",
    "home",
    "gear_trajectory",
    "gearing",
    "homing",
    "ElectronicGear",
    "FollowEx",
    "FollowExSetup",
    "FollowSegment",
    "PvtAxis",
    "PvtCurve",
    "PvtTables",
    "ReturnCode",
    "follow_cam",
    "follow_trajectory",
    "pvt",
    "pvt_complete_calculate",
    "pvt_continuous_calculate",
    "pvt_percent_calculate",
    "pvt_start",
    "pvt_table",
    "pvt_table_complete",
    "pvt_table_continuous",
    "pvt_table_continuous_ex",
    "pvt_table_ex",
    "pvt_table_percent",
    "pvt_trajectory",
    "CoordSystem",
    "LookAheadParams",
    "AdlinkInterpolator",
    "AdlinkInterpSetup",
    "AdlinkRun",
    "BlendMode",
    "CrdFifoPair",
    "GeLookAhead",
    "GeLookAheadParams",
    "run_adlink",
    "PathGenerator",
    "PathGeometryError",
    "PathRun",
    "PathSegment",
    "PathSetup",
    "paths",
    "plan_polyline_lookahead",
    "run_path",
    "GtGear",
    "GeJog",
    "GeSCurve",
    "GeTCurve",
    "GtJog",
    "GtSCurve",
    "GtTCurve",
    "MotionCommandRefused",
    "ProfileGenerator",
    "jog_trajectory",
    "motion",
    "move_trajectory",
    "ApsServoLaw",
    "Axis",
    "AxisRun",
    "Dac",
    "Encoder",
    "FloatBiquad",
    "GtServoLaw",
    "MoveMetrics",
    "RigidPlant",
    "DEFAULT_SIGNALS",
    "LtiPlant",
    "interop",
    "lti_plant",
    "to_control",
    "SIGNALS",
    "ServoPositionDrive",
    "StepperDrive",
    "SIGNAL_UNITS",
    "Switches",
    "TorqueDrive",
    "TwoMassPlant",
    "VelocityDrive",
    "Trajectory",
    "demo_axis",
    "design",
    "move_metrics",
    "plot",
    "trapezoid_move",
    "widgets",
]

_limit_dir_to_all(__name__)  # tab completion offers __all__, not np/sys/csv (servobench/_public.py)
