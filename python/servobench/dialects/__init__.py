"""Vendor programming interfaces on the virtual :class:`~servobench.Card`, one module per manual family.

* :mod:`servobench.dialects.gt` -- the Googol GT series (``GT_Axis(n)`` current-axis style, per-sample units).
* :mod:`servobench.dialects.aps` -- the ADLINK APS library (axis IDs from 0, pulse/s, PRA_* parameter numbers).

Each dialect only translates names, argument order, units and return codes; the behaviour is the Card's.
The GE and GUC-ECAT/iDEABOX dialects are to come.
"""

from . import aps, gt

__all__ = ["aps", "gt"]
