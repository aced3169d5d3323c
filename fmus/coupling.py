"""The law-plant coupling (port names, units, the law's linearisation): re-exported from
:mod:`friction.coupling`, its one home below ``plants`` and ``fmus``."""
from friction.coupling import (COUPLING_OUTPUTS, INPUT_INFO, LAW_PORTS, MEAN_INPUT,
                               PLANT_INPUTS, PLANT_OUTPUTS, PLANT_PORTS, SHARE_INPUT,
                               SWITCH_OUTPUTS, fmi_unit, has_switch, law_inputs,
                               law_linearisation, switch_linearisation)

__all__ = ["INPUT_INFO", "COUPLING_OUTPUTS", "SWITCH_OUTPUTS", "SHARE_INPUT", "MEAN_INPUT",
           "PLANT_INPUTS", "PLANT_OUTPUTS", "LAW_PORTS", "PLANT_PORTS", "fmi_unit", "law_inputs",
           "has_switch", "law_linearisation", "switch_linearisation"]
