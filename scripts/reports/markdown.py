"""Writing the reports' markdown pages (reproduce.py, beyond_paper.py): numbers as their tables show
them, and a page built line by line."""


def number(x, digits):
    """x to `digits` significant digits (whole above 1e4); an em dash for a missing value."""
    if x is None:
        return "—"
    return f"{x:.{digits}g}" if abs(x) < 1e4 else f"{x:.0f}"


class Page:
    """The lines of one page: page(line) adds a line, page.save(path) writes them all."""

    def __init__(self):
        self.lines = []

    def __call__(self, line):
        self.lines.append(line)

    def save(self, path):
        with open(path, "w") as out:
            out.write("\n".join(self.lines) + "\n")


def benchmark_table(page, headings, results, cells, classes):
    """A benchmark's table (a row per (class, law, summary) of `results`, `cells(summary)` after
    class and law) and the list of its classes {name: what}."""
    page("| " + " | ".join(headings) + " |")
    page("|" + "---|" * len(headings))
    for name, law, summary in results:
        page("| " + " | ".join([name, law] + cells(summary)) + " |")
    page("")
    page("Classes:")
    for name, what in classes.items():
        page(f"- `{name}`: {what}")


def table_rows(text):
    """A markdown table's rows as lists of cells (header first, separator dropped)."""
    rows = [line.strip("|").split("|") for line in text.splitlines() if line.startswith("|")]
    return [[c.strip() for c in row] for row in rows if not set("".join(row)) <= set("-: ")]
