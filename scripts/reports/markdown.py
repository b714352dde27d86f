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
