"""Native FMI 2.0 FMUs: the friction laws in plain C, no Python at run time.

:mod:`fmus.native.ckernels` compiles the laws' C sources (``csrc/``) into a shared library
and calls them through ctypes (tests, benchmarks); the FMU build, its generated variable table
and ``modelDescription.xml`` live in :mod:`fmus.native.build`.
"""
