"""frictionlab: the command-line front end and the end-to-end demo.

The library lives in the top-level packages ``friction``, ``plants``, ``fmus``,
``identification`` and ``diagnosis``; this package only parses commands, shows progress and
runs the demo.
"""
__version__ = "0.1.0"
