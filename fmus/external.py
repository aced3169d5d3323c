"""Run the same FMUs under external co-simulation tools (for cross-checks).

* :func:`run_libcosim` - OSP libcosim (C++ engine, via ``libcosimpy``), fixed-step
  algorithm: every slave steps with the inputs transferred at the previous communication
  point (our master's ``algorithm="jacobi"``);
* :func:`make_container` - a container FMU assembled by ``fmu-manipulation-toolbox``
  (the embedded FMUs and their links inside one FMU, run by its own fixed-step loop).

Both take the same ``fmus`` / ``connections`` / ``parameters`` arguments as
:class:`fmus.master.Master` and return (or build something that returns) results with the
same column names.
"""
from __future__ import annotations

import json
import os
import pathlib
import shutil

import numpy as np

__all__ = ["run_libcosim", "make_container"]


def _split(ref):
    inst, _, var = ref.partition(".")
    return inst, var


def run_libcosim(fmus: dict, connections, *, step_size: float, stop_time: float,
                 parameters: dict | None = None, record=None) -> np.ndarray:
    """Co-simulate with OSP libcosim's fixed-step algorithm; returns a structured array
    (``time`` first, then ``record`` columns ``"instance.variable"``) at every step after
    the start.

    Parameters
    ----------
    fmus : dict
        ``{instance name: path of its .fmu}``.
    connections : sequence of (str, str)
        ``("instance.output", "instance.input")`` pairs.
    step_size : float
        Communication step [s].
    stop_time : float
        End of the run [s].
    parameters : dict, optional
        ``{instance: {variable: value}}``.
    record : list of str, optional
        ``"instance.variable"`` to record.
    """
    from fmpy import read_model_description
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave

    try:  # libcosim logs every FMI call at debug level by default
        from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
        log_output_level(CosimLogLevel.WARNING)
    except ImportError:
        pass
    # libcosim crashes the process (SIGSEGV) on a missing or unreadable FMU: every file is
    # read with fmpy first, whose errors name it
    vrs = {}
    for name, path in fmus.items():
        path = os.fspath(path)
        if not os.path.isfile(path):
            raise FileNotFoundError(f"FMU of instance {name!r} not found: {path}")
        try:
            md = read_model_description(path)
        except Exception as exc:
            raise ValueError(f"FMU of instance {name!r} ({path}) is not a readable FMU: "
                             f"{exc}") from exc
        vrs[name] = {v.name: (v.valueReference, v.type) for v in md.modelVariables}
    ns = int(round(step_size * 1e9))
    ex = CosimExecution.from_step_size(step_size=ns)
    idx = {}
    for name, path in fmus.items():
        slave = CosimLocalSlave(fmu_path=os.path.abspath(os.fspath(path)), instance_name=name)
        idx[name] = ex.add_local_slave(local_slave=slave)
    for inst, values in (parameters or {}).items():
        for var, val in values.items():
            vr, typ = vrs[inst][var]
            if typ == "Real":
                ex.real_initial_value(slave_index=idx[inst], variable_reference=vr,
                                      value=float(val))
            elif typ == "Boolean":
                ex.boolean_initial_value(idx[inst], vr, bool(val))
            elif typ == "String":
                ex.string_initial_value(idx[inst], vr, str(val))
            else:
                ex.integer_initial_value(idx[inst], vr, int(val))
    for src, dst in connections:
        si, sv = _split(src)
        di, dv = _split(dst)
        ok = ex.connect_real_variables(idx[si], vrs[si][sv][0], idx[di], vrs[di][dv][0])
        if ok is False or ok == -1:
            raise RuntimeError(f"libcosim refused the connection {src} -> {dst}")
    obs = CosimObserver.create_last_value()
    ex.add_observer(observer=obs)
    record = list(record)
    n = int(round(stop_time / step_size))
    out = np.empty((n, len(record)))
    cols = [(idx[_split(r)[0]], vrs[_split(r)[0]][_split(r)[1]][0]) for r in record]
    for k in range(n):
        if not ex.step():
            raise RuntimeError(f"libcosim step {k + 1} failed")
        for j, (si, vr) in enumerate(cols):
            out[k, j] = obs.last_real_values(si, [vr])[0]
    res = np.empty(n, dtype=[("time", "f8")] + [(r, "f8") for r in record])
    res["time"] = step_size * np.arange(1, n + 1)
    for j, r in enumerate(record):
        res[r] = out[:, j]
    return res


def make_container(fmus: dict, connections, out_path, *, step_size: float,
                   parameters: dict | None = None, sequential: bool = True,
                   expose=()) -> pathlib.Path:
    """Build a container FMU with fmu-manipulation-toolbox.

    ``sequential=True``: the container steps the embedded FMUs one after the other in the
    order of ``fmus`` (our Gauss-Seidel); ``expose`` lists ``"instance.variable"`` outputs to
    expose as container outputs, named ``instance_variable``.

    Parameters
    ----------
    fmus : dict
        ``{instance name: path of its .fmu}``, in stepping order.
    connections : sequence of (str, str)
        ``("instance.output", "instance.input")`` pairs.
    out_path : str or path
        The container ``.fmu`` to write.
    step_size : float
        Communication step [s].
    parameters : dict, optional
        ``{instance: {variable: value}}``.
    sequential : bool
        See above.
    expose : sequence of str
        See above.
    """
    from fmu_manipulation_toolbox.assembly import Assembly

    out_path = pathlib.Path(out_path)
    work = out_path.parent / (out_path.stem + "_src")
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    files = {}
    for name, path in fmus.items():
        fname = f"{name}.fmu"
        shutil.copy(os.fspath(path), work / fname)
        files[name] = fname
    desc = {
        "name": out_path.name, "step_size": step_size, "mt": False,
        "sequential": bool(sequential), "auto_link": False, "auto_input": False,
        "auto_output": False, "auto_parameter": False,
        "fmu": [files[n] for n in fmus],
        "link": [[files[_split(s)[0]], _split(s)[1], files[_split(d)[0]], _split(d)[1]]
                 for s, d in connections],
        "output": [[files[_split(r)[0]], _split(r)[1], r.replace(".", "_")] for r in expose],
        "start": [[files[i], var, str(val)] for i, vals in (parameters or {}).items()
                  for var, val in vals.items()],
    }
    (work / "assembly.json").write_text(json.dumps(desc, indent=1))
    asm = Assembly("assembly.json", fmu_directory=work)
    asm.make_fmu()
    built = work / out_path.name
    shutil.move(str(built), out_path)
    return out_path
