"""bearingheat template: writes the template, refuses to overwrite, exit codes 0/2."""
from __future__ import annotations

from bearingheat.cli import main


def test_template_cli(tmp_path, capsys):
    target = tmp_path / "supports.xlsx"
    assert main(["template", "-o", str(target)]) == 0
    assert capsys.readouterr().out == (f"template written to {target}; fill in the sheet 'Supports', then run: "
                                       f"bearingheat calc {target} -o results.xlsx\n")
    assert main(["template", "-o", str(target)]) == 2
    assert capsys.readouterr().err == f"bearingheat template: error: {target} exists; give --force to replace it\n"
    assert main(["template", "-o", str(target), "--force", "-q"]) == 0
    assert main(["template", "-o", str(tmp_path / "t.csv")]) == 2
    assert capsys.readouterr().err == (f"bearingheat template: error: {tmp_path / 't.csv'}: the template is an "
                                       ".xlsx workbook; name it e.g. supports.xlsx\n")
