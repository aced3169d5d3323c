"""Seed 003's protocol: the control-based second-order fit, and the full protocol (slow)."""
import numpy as np
import pytest

from identification.xml350_protocol import PAPER_ACCURACY, fit_second_order


def test_second_order_fit_recovers_sigma0_sigma1_from_a_noisy_response():
    M, s0, s1 = 11.8, 1.102e7, 1.46e3
    f = np.linspace(5, 500, 300)
    s = 2j * np.pi * f
    G = 1.0 / (M * s * s + s1 * s + s0)
    rng = np.random.default_rng(0)
    G = G * (1 + 0.02 * (rng.standard_normal(f.size) + 1j * rng.standard_normal(f.size)))
    r = fit_second_order(f, G, M, band=(20, 400))
    assert r["sigma0"] == pytest.approx(s0, rel=0.01)
    assert r["sigma1"] == pytest.approx(s1, rel=0.05)
    assert r["wn"] == pytest.approx(np.sqrt(s0 / M), rel=0.005)
    # the control transfer function is the fitted model
    assert abs(r["tf"](0)) == pytest.approx(1 / r["sigma0"], rel=1e-9)
    with pytest.raises(ValueError, match="fewer than 3"):
        fit_second_order(f, G, M, band=(1000, 2000))


@pytest.mark.slow
def test_xml350_protocol_end_to_end():
    from identification.xml350_protocol import run_xml350_protocol
    out = run_xml350_protocol(quick=True)
    # static and dynamic steps land near the stage's own friction (Table I, final)
    assert out["init_error"]["Fc"] < 0.1 and out["init_error"]["sigma0"] < 0.1
    # refinement improves on the initial model and beats the paper's real-stage accuracy
    h = out["cost_history"]
    assert h[-1] <= h[0]
    assert out["accuracy"]["identification"] >= PAPER_ACCURACY["identification"]
    assert out["accuracy"]["validation"] >= PAPER_ACCURACY["validation"]
