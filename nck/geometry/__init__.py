"""Geometry of the part program: frames, planes, circles, polar coordinates, tool offsets.

Pure library (stdlib + numpy), used by the interpreter's motion builder:

* :mod:`~nck.geometry.frames`, :mod:`~nck.geometry.transform`, :mod:`~nck.geometry.chain` —
  frame components, TRANS…AMIRROR, the chain base : settable : programmable, G53/G153/SUPA;
* :mod:`~nck.geometry.frame_vars`, :mod:`~nck.geometry.frame_functions` — ``$P_UIFR``,
  ``$P_PFRAME`` …, CTRANS/CROT/CSCALE/CMIRROR/CFINE and the ``:`` chain;
* :mod:`~nck.geometry.planes`, :mod:`~nck.geometry.units` — G17/G18/G19, G70/G71/G700/G710;
* :mod:`~nck.geometry.circles` — IJK, CR, AR, CIP, CT, helix/TURN, end-point monitoring;
* :mod:`~nck.geometry.polar` — G110/G111/G112, RP/AP;
* :mod:`~nck.geometry.contour_aids`, :mod:`~nck.geometry.path_aids` — CHF/CHR/RND/RNDM;
* :mod:`~nck.geometry.tool_length` — tool length per type and plane;
* :mod:`~nck.geometry.path_builder`, :mod:`~nck.geometry.path_state` — one block's path in
  WCS and MCS, and the geometric modal state;
* :mod:`~nck.geometry.arc_mcs` — plane and direction of an arc in the machine;
* radius compensation: :mod:`~nck.geometry.radius_comp` and the ``trc_*`` modules.
"""
