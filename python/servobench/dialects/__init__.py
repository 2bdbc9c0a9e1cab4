"""Vendor programming interfaces on the virtual :class:`~servobench.Card`, one module per manual family.

* :mod:`servobench.dialects.gt` -- the Googol GT series (``GT_Axis(n)`` current-axis style, per-sample units).
* :mod:`servobench.dialects.aps` -- the ADLINK APS library (axis IDs from 0, pulse/s, PRA_* parameter numbers).
* :mod:`servobench.dialects.ge` -- the Googol GE series (explicit axis argument from 1, pulse/ms units, PX/SX).
* :mod:`servobench.dialects.gts` -- the Googol GUC-ECAT / iDEABOX advanced functions (crd FIFOs and look-ahead,
  PVT tables, FollowEx; axes and crd from 1, pulse, ms, pulse/ms).

Each dialect only translates names, argument order, units and return codes; the behaviour is the Card's.

The return codes are typed, one enum per manual, defined in C++ (``cpp/include/servobench/vendor/``) with the
manual's values: :class:`GtCode` (GT Table 2-1), :class:`GeCode` (GE Tables 2-1/2-2), :class:`GucCode` (GUC-ECAT
and iDEABOX), :class:`AdlinkCode` (ADLINK ``ErrorCodeDef.h``). Each is an ``int``-valued enum
(``int(GtCode.MAP_AXIS_ERROR) == 6``). The card's exceptions carry their cause as data: a
:class:`~servobench.PathGeometryError` has ``gt_code`` (2, 3, 5 or 6), a :class:`~servobench.CardCommandRefused`
has ``fault`` (the kernel's cause, e.g. ``"mode_change_in_motion"``) and ``axis`` (0-based, -1 card-wide).
"""

from .._core import AdlinkCode, GeCode, GtCode, GucCode
from . import aps, ge, gt, gts

__all__ = ["aps", "ge", "gt", "gts", "AdlinkCode", "GeCode", "GtCode", "GucCode"]
