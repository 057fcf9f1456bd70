"""LibreOffice headless: recalculate workbooks and render sheets to PNG.

Used by the test that checks the live formulas of ``calc --formulas`` with a
real spreadsheet engine, and by the script that draws the screenshots of
docs/excel.md. Each call runs ``soffice --headless --convert-to`` with a
private, throw-away user profile (so it neither disturbs nor waits for
another LibreOffice of the same user) that is set to recalculate every
formula when a file is loaded.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

__all__ = ["soffice", "convert"]

# LibreOffice: Tools > Options > Calc > Formula > "Recalculation on file load": always (0)
_PROFILE = """<?xml version="1.0" encoding="UTF-8"?>
<oor:items xmlns:oor="http://openoffice.org/2001/registry" xmlns:xs="http://www.w3.org/2001/XMLSchema"
 xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
<item oor:path="/org.openoffice.Office.Calc/Formula/Load"><prop oor:name="OOXMLRecalcMode" oor:op="fuse">
<value>0</value></prop></item>
<item oor:path="/org.openoffice.Office.Calc/Formula/Load"><prop oor:name="ODFRecalcMode" oor:op="fuse">
<value>0</value></prop></item>
</oor:items>
"""


def soffice() -> str | None:
    """Path of the LibreOffice program, None when it is not installed."""
    return shutil.which("soffice") or shutil.which("libreoffice")


def convert(paths, to: str, outdir, *, timeout: float = 300.0) -> list[Path]:
    """Convert workbooks with LibreOffice (``to`` e.g. 'xlsx', 'png'); returns the files written.

    Raises RuntimeError with LibreOffice's output when a file is not written.
    """
    program = soffice()
    if program is None:
        raise RuntimeError("LibreOffice (soffice) is not installed")
    paths = [Path(p) for p in paths]
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="bearingheat-lo-") as profile:
        user = Path(profile) / "user"
        user.mkdir()
        (user / "registrymodifications.xcu").write_text(_PROFILE, encoding="utf-8")
        command = [program, "--headless", "--norestore", "--nolockcheck",
                   f"-env:UserInstallation={Path(profile).as_uri()}",
                   "--convert-to", to, "--outdir", str(outdir), *map(str, paths)]
        env = dict(os.environ, HOME=profile)
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, env=env)
    extension = to.split(":")[0]
    written = [outdir / f"{p.stem}.{extension}" for p in paths]
    missing = [str(p) for p in written if not p.is_file()]
    if missing:
        raise RuntimeError(f"LibreOffice did not write {', '.join(missing)} (exit {done.returncode}): "
                           f"{done.stdout.strip()} {done.stderr.strip()}")
    return written
