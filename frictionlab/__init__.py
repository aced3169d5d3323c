"""frictionlab: the command-line front end and the end-to-end demo.

The library lives in the top-level packages ``friction``, ``plants``, ``fmus``,
``identification`` and ``diagnosis``; this package only parses commands, turns progress on
or off (``--quiet``; the convention is :mod:`friction.progress`, re-exported as
:mod:`frictionlab.progress`) and runs the demo (:mod:`frictionlab.demo`, whose stages hold
the demo code and figures the library packages do not).
"""
__version__ = "0.1.0"
