"""The table model of the Parameter/Setup lists: cursor bounds, scrolling, drawing."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from hmi.widgets.data_table import Cell, Column, DataTable, TableCursor, render_table


def table(rows: int) -> DataTable:
    columns = [Column("Name", 6, "<"), Column("A", 8), Column("B", 8)]
    return DataTable("T", columns, [
        [Cell(f"R{i}"), Cell(f"{i}.0", f"A{i}", str(i), 5), Cell("x")] if i % 2 else
        [Cell(f"R{i}"), Cell(f"{i}.0", f"A{i}", str(i), 5), Cell("y", f"B{i}", "y", 7)]
        for i in range(rows)
    ], "note")


@settings(max_examples=60, deadline=None)
@given(rows=st.integers(0, 40), height=st.integers(4, 20),
       moves=st.lists(st.tuples(st.integers(-25, 25), st.integers(-2, 2)), max_size=12))
def test_cursor_stays_in_the_table_and_on_display(rows: int, height: int, moves: list) -> None:
    data = table(rows)
    cursor = TableCursor()
    for down, right in moves:
        cursor.move(data, down, right)
        text = render_table(data, cursor, height, 7).plain
        assert len(text.splitlines()) == height
        if rows:
            assert 0 <= cursor.row < rows
            assert cursor.top <= cursor.row < cursor.top + height - 3
            assert cursor.column in data.editable_columns()
            assert data.cell(cursor.row, cursor.column) is not None


def test_cells_the_level_may_not_write_are_dimmed_and_the_selected_one_inverse() -> None:
    data = table(3)
    cursor = TableCursor(row=1, column=1)
    text = render_table(data, cursor, 10, 6)
    styles = {text.plain[span.start:span.end].strip(): str(span.style) for span in text.spans}
    assert styles["1.0"] == "reverse"
    assert styles["0.0"] == "dim"  # needs level 5, current 6
    assert "y" not in styles or "dim" not in styles["y"]  # level 7 data: normal
