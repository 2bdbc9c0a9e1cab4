"""Vendor programming interfaces on the virtual :class:`~servobench.Card`, one module per manual family.

* :mod:`servobench.dialects.gt` -- the Googol GT series (``GT_Axis(n)`` current-axis style, per-sample units).
* :mod:`servobench.dialects.aps` -- the ADLINK APS library (axis IDs from 0, pulse/s, PRA_* parameter numbers).
* :mod:`servobench.dialects.ge` -- the Googol GE series (explicit axis argument from 1, pulse/ms units, PX/SX).
* :mod:`servobench.dialects.gts` -- the Googol GUC-ECAT / iDEABOX advanced functions (crd FIFOs and look-ahead,
  PVT tables, FollowEx; axes and crd from 1, pulse, ms, pulse/ms).

Each dialect only translates names, argument order, units and return codes; the behaviour is the Card's.
"""

from . import aps, ge, gt, gts

__all__ = ["aps", "ge", "gt", "gts"]
