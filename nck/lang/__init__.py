"""The NC language front end (Siemens mode of the 840D sl / 828D).

Pipeline: :mod:`nck.lang.lexer` (tokens) → :mod:`nck.lang.parser` (one block →
:class:`nck.lang.ast.Block`; expressions in :mod:`nck.lang.expressions`,
declarations in :mod:`nck.lang.declarations`) → the interpreter in
:mod:`nck.interp`. G groups are data: :mod:`nck.lang.gcodes` reads
``data/gcode/siemens.toml``.

What the language covers:

* Blocks: ``N…`` and ``:…`` numbers, ``/`` and ``/0``…``/9`` skip levels, ``;``
  comments, ``LABEL:``, ``%`` header lines, 512-character block limit (12540).
* Words: ``X10``, ``X=R1+5``, ``X=AC(…)``/``IC(…)``, extended addresses ``X1=``,
  ``M2=``, ``S1=``, ``I1=``, ``CR=``, ``AR=``, ``RP=``, ``AP=``, ``TURN=``, ``AX[…]=``.
* Values: R parameters (``R10``, ``R[expr]``), ``DEF`` INT/REAL/BOOL/CHAR/
  STRING[n]/AXIS/FRAME with arrays (up to 3 dimensions), initial values (list,
  ``SET``, ``REP``), ``LLI``/``ULI`` limits, ``DEF NCK|CHAN`` global data; system
  variables ``$AA_IM``, ``$P_…``, ``$TC_DP…``, ``$M…``/``$S…`` machine and setting data.
* Expressions with the 840D operator priority, ``'H…'``/``'B…'`` constants,
  ``EX`` exponents, and functions (trigonometry in degrees, SQRT, POT, ABS,
  TRUNC, ROUND, ROUNDUP, LN, EXP, MINVAL, MAXVAL, BOUND, string functions,
  SPRINT, AXNAME, ISAXIS, ISVAR).
* Flow: GOTOF/GOTOB/GOTO/GOTOC/GOTOS, IF/ELSE/ENDIF, WHILE, FOR…TO, LOOP,
  REPEAT…UNTIL, CASE…OF…DEFAULT, REPEAT/REPEATB section repetition;
  subprograms by name or ``L…`` with ``P`` passes, ``PROC`` parameters by value
  and ``VAR`` reference, ``SAVE``, ``EXTERN``, ``MCALL``, ``CALL``; M17/RET/M2/M30;
  the drilling cycles CYCLE81/82/83 are NC programs in ``data/cycles``.

Every error is an :class:`nck.errors.NcAlarmError` with its SINUMERIK number.
"""
