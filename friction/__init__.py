"""Friction laws of the LuGre family, with stable numerics and a reference integrator.

>>> from friction import MODELS, make_model
>>> model = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
"""
from __future__ import annotations

from ._validation import ParameterError
from .base import METHODS, FrictionModel, FrictionParams, ParamInfo, param
from .dataset import Dataset, load_csv, load_dataset, load_mat
from .backlash import BacklashLuGre
from .gms import GMS
from .load_lugre import LoadLuGre
from .lugre import LuGre, LuGreParams
from .modified_lugre import ModifiedLuGre
from .mre_lugre import MRELuGre
from .stribeck import StaticStribeck

__all__ = ["MODELS", "make_model", "FrictionModel", "FrictionParams", "ParamInfo", "param",
           "ParameterError", "METHODS", "LuGre", "LuGreParams", "Dataset", "load_csv",
           "load_mat", "load_dataset", "StaticStribeck", "ModifiedLuGre", "LoadLuGre",
           "MRELuGre", "GMS", "BacklashLuGre"]

#: registry name -> model class (a law module that fails to import fails ``import friction``)
MODELS: dict[str, type[FrictionModel]] = {
    "lugre": LuGre, "stribeck": StaticStribeck, "modified_lugre": ModifiedLuGre,
    "load_lugre": LoadLuGre, "mre_lugre": MRELuGre, "gms": GMS, "backlash_lugre": BacklashLuGre}


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
