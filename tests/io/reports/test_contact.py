"""The figure of the working contact angle against the axial load (Zaitsev & Voronkin example bearing)."""
from bearingheat.io.reports.contact import DEFAULT_PATH, plot_alpha_vs_axial_load


def test_plot_is_deterministic(tmp_path):
    first = plot_alpha_vs_axial_load(tmp_path / "a.png").read_bytes()
    second = plot_alpha_vs_axial_load(tmp_path / "b.png").read_bytes()
    assert first == second and first[:8] == b"\x89PNG\r\n\x1a\n"
    assert DEFAULT_PATH.is_file() and DEFAULT_PATH.stat().st_size < 100_000
