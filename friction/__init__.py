"""Friction laws of the LuGre family, with stable numerics and a reference integrator.

>>> from friction import MODELS, make_model
>>> model = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
"""
from __future__ import annotations

from ._validation import ParameterError
from .base import METHODS, FrictionModel, FrictionParams, ParamInfo, param
from .dataset import Dataset, load_csv, load_dataset, load_mat
from .lugre import LuGre, LuGreParams

__all__ = ["MODELS", "make_model", "FrictionModel", "FrictionParams", "ParamInfo", "param",
           "ParameterError", "METHODS", "LuGre", "LuGreParams", "Dataset", "load_csv",
           "load_mat", "load_dataset"]

#: registry name -> model class
MODELS: dict[str, type[FrictionModel]] = {"lugre": LuGre}


def _register_optional():
    # laws land module by module; each registers itself here once it exists
    import importlib
    for mod, cls, name in (("stribeck", "StaticStribeck", "stribeck"),
                           ("modified_lugre", "ModifiedLuGre", "modified_lugre"),
                           ("load_lugre", "LoadLuGre", "load_lugre"),
                           ("mre_lugre", "MRELuGre", "mre_lugre"),
                           ("gms", "GMS", "gms"),
                           ("backlash", "BacklashLuGre", "backlash_lugre")):
        try:
            m = importlib.import_module(f"{__name__}.{mod}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{mod}":
                raise
            continue
        except Exception as exc:  # a broken law must not take the others down; tests catch it
            import warnings
            warnings.warn(f"friction law module {mod!r} failed to import: {exc!r}")
            continue
        MODELS[name] = getattr(m, cls)
        globals()[cls] = MODELS[name]
        __all__.append(cls)


_register_optional()


def make_model(name: str, params: FrictionParams | None = None, **kwargs) -> FrictionModel:
    """Create a friction law by registry name.

    Parameters
    ----------
    name : str
        One of ``MODELS`` (``lugre``, ``modified_lugre``, ``load_lugre``, ``mre_lugre``,
        ``stribeck``, ``gms``, ``backlash_lugre``).
    params : FrictionParams, optional
        A parameter dataclass instance; keyword arguments override its fields.
    **kwargs
        Parameter values (SI units), validated against their bounds.
    """
    try:
        cls = MODELS[name]
    except KeyError:
        raise ValueError(f"unknown friction model {name!r}; choose from {sorted(MODELS)}") from None
    return cls(params, **kwargs)
