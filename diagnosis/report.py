"""The diagnosis report both levels return: the contract's JSON (``baseline``, ``where``,
``effects``, ``verdict``) plus details, and the sections they share."""
from __future__ import annotations

import json

import numpy as np

__all__ = ["DiagnosisReport", "report_sections", "EFFECT_KEYS"]


class DiagnosisReport(dict):
    """The contract's diagnosis JSON plus details; ``to_json()`` writes it."""

    def to_json(self, path=None, indent=2) -> str:
        """JSON text of the report; also written to ``path`` if given.

        Parameters
        ----------
        path : str or path, optional
            Write the text to this file too.
        indent : int
            JSON indentation.
        """
        text = json.dumps(self, indent=indent, default=_plain)
        if path is not None:
            with open(path, "w") as fh:
                fh.write(text)
        return text

    def summary(self) -> str:
        b, v = self["baseline"], self["verdict"]
        lines = [f"baseline {b['model']}: fit NRMSE {b['fit']:.4g}, validation NRMSE "
                 f"{b['validation']:.4g} (noise floor {self['noise_floor']:.3g})",
                 "where (held-out residual energy):"]
        for w in self["where"][:4]:
            lines.append(f"  {w['share'] * 100:5.1f} %  {w['label']}  (NRMSE {w['nrmse']:.3g})")
        lines.append("which (held-out validation NRMSE before -> after):")
        for e in self["effects"]:
            z = f"  z {e['significance_z']:5.1f}" if "significance_z" in e else ""
            lines.append(f"  {e['name']:15s} {e['validation_before']:.4g} -> "
                         f"{e['validation_after']:.4g}  gap closed {e['gap_closed'] * 100:6.1f} %"
                         + z)
        lines.append(f"verdict: {v['cause']} (gap closed {v['gap_closed'] * 100:.1f} %)")
        if self.get("transfer"):
            lines.append(f"scored by transfer: {self['transfer']['explanation']}")
        return "\n".join(lines)


def _plain(o):
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    return str(o)



#: keys of each ranked effect in the report
EFFECT_KEYS = ("name", "validation_before", "validation_after", "gap_closed", "excess_closed",
               "significance_z", "improvement_z", "noise_z", "imprint", "size_reason",
               "defers_to", "defer_reason", "deferral_overruled", "protocol")


def report_sections(where, bands, freq, effects, verdict, sequence, before, final_val,
                    floor) -> dict:
    """The report sections both levels share: the contract's ``where``, ``effects`` and
    ``verdict``, plus ``where_bands``, ``where_frequency``, ``greedy`` and ``noise_floor``."""
    gap = max(before - floor, 1e-12)
    left = max(final_val - floor, 0.0)
    return {"where": where,
            "effects": [{k: e[k] for k in EFFECT_KEYS if k in e} for e in effects],
            "verdict": verdict, "where_bands": bands[:12], "where_frequency": freq,
            "greedy": {"sequence": sequence, "validation_final": final_val,
                       "unexplained_nrmse": left, "unexplained_share_of_gap": left / gap},
            "noise_floor": floor}

