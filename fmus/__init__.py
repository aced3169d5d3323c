"""FMI 2.0 co-simulation FMUs of the friction laws and plants, and an fmpy co-simulation master.

>>> from fmus.build import build_all           # doctest: +SKIP
>>> paths = build_all("out/fmus")               # doctest: +SKIP
>>> from fmus.master import Master, Connection  # doctest: +SKIP
"""
__all__ = ["build", "master", "runtime", "modeldescription", "vendor"]
