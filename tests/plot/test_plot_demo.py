"""The demo's pictures: what they print agrees with the demo's tables; nothing is clipped."""

import re

import numpy as np
import pytest
from figure_checks import texts_outside, titles_and_labels

from andoyer.cli import demo_report
from andoyer.cli.demo_report import DemoContext
from andoyer.planetary.precession import ARCSEC, precession_rates


@pytest.fixture(scope="module")
def earth_precession():
    return demo_report.precession_figure()


def test_demo_precession_plot_slope_is_the_secular_rate(earth_precession):
    # The averaged (secular) model is an independent computation of the mean rate; the plot fits
    # one state's node over two lunar nodal periods with its nutation terms. Measured agreement
    # 1.7e-5 (50.3994 against 50.4002″/yr, the IAU H; 50.4781 against 50.4788 with Lara's); a
    # straight line alone gave 52.2″/yr over 18.6 years (Lara's H).
    figure, rates = earth_precession
    data = figure.andoyer_data
    assert data.axis == "momentum"
    plotted = -data.precession_rate / ARCSEC  # p = −⟨ḣ⟩, ″ per year (times in years)
    assert plotted == pytest.approx(precession_rates("earth").secular, rel=1e-4)
    assert rates.secular == pytest.approx(precession_rates("earth").secular, rel=1e-12)


def test_demo_precession_legend_agrees_with_the_table(earth_precession, tmp_path, monkeypatch):
    figure, rates = earth_precession
    monkeypatch.setattr(demo_report, "precession_figure", lambda: earth_precession)  # computed once
    legend = figure.axes[0].get_lines()[1].get_label()
    shown = re.search(r"p = -\\dot\\Omega\$ = ([-0-9.]+)″", legend)
    assert shown, legend
    assert float(shown.group(1)) > 0
    assert float(shown.group(1)) == pytest.approx(rates.secular, abs=0.01)
    text = demo_report.section_precession(DemoContext("earth", tmp_path))
    assert "p = −⟨ḣ⟩" in text
    table = re.search(r"secular \(averaged\) model \| ([-0-9.]+) \|", text)
    assert float(table.group(1)) == pytest.approx(float(shown.group(1)), abs=0.01)


def test_demo_precession_texts_inside_the_figure(earth_precession):
    figure, _ = earth_precession
    assert texts_outside(figure, titles_and_labels(figure)) == []
    assert np.isfinite(figure.andoyer_data.precession_rate)


@pytest.mark.parametrize("name", ["earth", "eros"])
def test_demo_pictures_titles_and_labels_inside_the_figure(name):
    # The demo draws these for its body (section_pictures): an Earth's G = 7.29e-5 made the
    # titles of the Poinsot picture and of the sphere wider than their axes.
    from andoyer import bodies, plot

    body = bodies.get(name)
    state = demo_report.demo_state(name)
    G = float(state.as_andoyer().G)
    for fig in (
        plot.phase_portrait(body, G, n_points=91, momentum_unit="$C$ rad/s"),
        plot.momentum_sphere(body, G, n_points=91),
        plot.poinsot(body, demo_report.demo_state(name, demo_report.SAM_NUTATIONS[-1])),
    ):
        assert texts_outside(fig, titles_and_labels(fig)) == []
