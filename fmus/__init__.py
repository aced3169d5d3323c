"""FMI 2.0 co-simulation FMUs of the friction laws and plants, and an fmpy co-simulation master.

Modules: :mod:`fmus.coupling` (the law-plant coupling, re-exported from :mod:`friction.coupling`),
:mod:`fmus.variables` (the variables of both FMU kinds, from the parameter dataclasses),
:mod:`fmus.recipes` (the catalogue of pythonfmu FMUs), :mod:`fmus.build` (``build_all``),
:mod:`fmus.runtime` (the pythonfmu slave classes; travels inside the FMUs with coupling and
variables), :mod:`fmus.native` (the C FMUs), :mod:`fmus.modeldescription` (complete
``modelDescription.xml``), :mod:`fmus.vendor` (unique package names inside FMUs),
:mod:`fmus.status_shim` (the C shim in front of pythonfmu's binary: fmi2Error on bad input),
:mod:`fmus.master` (the co-simulation master), :mod:`fmus.proof` and :mod:`fmus.plant_fmus`
(co-simulation against the reference integrators), :mod:`fmus.external` (libcosim and
container-FMU runs). The demo stage is :mod:`frictionlab.demo.fmus_stage`.

>>> from fmus.build import build_all           # doctest: +SKIP
>>> paths = build_all("out/fmus")               # doctest: +SKIP
>>> from fmus.master import Master, Connection  # doctest: +SKIP
"""
__all__ = ["coupling", "variables", "recipes", "build", "master", "runtime", "modeldescription",
           "vendor", "proof", "plant_fmus",
           "external", "testing", "status_shim"]
