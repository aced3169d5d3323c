"""Worked studies on real machines: plant models of :mod:`plants` meeting measured data,
identified with :mod:`identification` and diagnosed with :mod:`diagnosis`.

They sit outside the plant library's core (which never imports the identification or the
diagnosis): :mod:`plants.studies.emps` - the EMPS benchmark axis simulated in closed and
open loop.
"""
