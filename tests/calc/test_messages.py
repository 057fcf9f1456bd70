"""Row status and messages as calc keeps them: categoricals written by their codes."""
import numpy as np
import pandas as pd
import pytest

import bearingheat as bh
from bearingheat.calc import messages


def test_row_status_joins_messages_and_an_error_replaces_warnings():
    status, message = messages.row_status(4, {1: ["w1", "w2"], 2: ["w3"], 3: []}, {2: ["e1"]})
    assert list(status) == ["ok", "warning", "error", "ok"]
    assert list(message) == ["", "w1; w2", "e1", ""]
    assert messages.status_codes(pd.Series(status)).tolist() == [messages.OK, messages.WARNING, messages.ERROR,
                                                                  messages.OK]


def test_status_codes_of_a_text_column():
    column = pd.Series(["ok", "error", "warning", "ok"])
    assert messages.status_codes(column).tolist() == [0, 2, 1, 0]


def test_with_texts_replaces_only_the_given_rows():
    column = pd.Series(pd.Categorical(["", "a", "", "b"]))
    changed = messages.with_texts(column, [0, 3], ["c", "a"])
    assert list(changed) == ["c", "a", "", "a"]
    assert list(column) == ["", "a", "", "b"]  # the column itself is left as it was
    assert list(messages.with_texts(np.array(["x", "y"], dtype=object), [1], ["z"])) == ["x", "z"]


def test_calc_writes_status_and_message_as_text():
    """The categoricals stay inside calc: the result has the text columns pandas makes of text."""
    rows = pd.DataFrame({"designation": ["6205", "6205"], "d [mm]": [25, 25], "D [mm]": [52, 52],
                         "C0 [kN]": [7.8, 7.8], "lubrication": ["oil_bath", "oil_bath"], "n [rpm]": [3000, 3000],
                         "Fr [kN]": [2, -1], "nu [mm^2/s]": [12, 12]})
    out = bh.calc(rows)
    text = pd.Series(["text"]).dtype
    assert out["status"].dtype == text and out["message"].dtype == text
    assert out["status"].tolist() == ["ok", "error"]
    assert out["message"].tolist() == ["", "Fr [kN]: -1 must be >= 0"]


@pytest.mark.parametrize("widths", [[99, 16], [15, 16]])
def test_messages_are_the_messages_of_the_rows_alone(widths):
    """Messages on a few rows are written into the message categorical by their codes; where many rows get one
    (B = 99 mm differs from the catalogue's 15 mm on every other row) calc keeps them as Python texts. Either
    way: the same status and messages as each row computed alone, and the same text columns."""
    rows = pd.DataFrame({"designation": ["6205", "6206"] * 8, "d [mm]": [25, 30] * 8, "D [mm]": [52, 62] * 8,
                         "B [mm]": widths * 8, "C0 [kN]": [7.8, 11.2] * 8, "lubrication": "oil_bath",
                         "n [rpm]": [3000, 1500] * 8, "Fr [kN]": [2, 3] * 8, "nu [mm^2/s]": 12})
    rows.loc[3, "Fr [kN]"] = -1
    out = bh.calc(rows)
    alone = [bh.calc(rows.iloc[[i]]) for i in range(len(rows))]
    assert out["status"].tolist() == [a["status"].iat[0] for a in alone]
    assert out["message"].tolist() == [a["message"].iat[0] for a in alone]
    assert set(out["status"]) == ({"warning", "error", "ok"} if widths[0] == 99 else {"error", "ok"})
    text = pd.Series(["text"]).dtype
    assert out["status"].dtype == text and out["message"].dtype == text


@pytest.mark.parametrize("text", ["ok", "", "exact root", "Mößbauer · 70 °C"])
def test_a_text_in_every_row_is_the_column_pyarrow_casts(text):
    """A result column with one text in every row is written from Arrow buffers (offsets stepping by the text's
    length in bytes): the same column as the dictionary cast of the general case."""
    import pyarrow as pa

    from bearingheat.calc.table import _text
    cells = pd.Categorical.from_codes(np.ones(1000, dtype=np.int8), categories=pd.Index(["x", text], dtype=object))
    written = _text(cells)
    assert written.dtype == pd.Series(["text"]).dtype and list(written) == [text] * 1000
    if written.dtype != object:  # pandas 3: Arrow text (pandas 2 keeps text as objects)
        cast = pa.DictionaryArray.from_arrays(pa.array(cells.codes), pa.array(["x", text], type=pa.large_string()))
        assert pd.array(cast.cast(pa.large_string()), dtype=written.dtype).equals(written)
    mixed = cells.copy()
    mixed[3] = "x"  # two texts: the general cast
    assert list(_text(mixed)) == [text] * 3 + ["x"] + [text] * 996
