"""Vendor programming interfaces on the virtual :class:`~servobench.Card`, one module per manual family.

* :mod:`servobench.dialects.gt` -- the Googol GT series (``GT_Axis(n)`` current-axis style, per-sample units).

Each dialect only translates names, argument order, units and return codes; the behaviour is the Card's.
The GE, GUC-ECAT/iDEABOX and ADLINK APS dialects are to come.
"""

from . import gt

__all__ = ["gt"]
