"""The rows of a file in Triangle's formats (.poly, .node), test-side and
independent of the core's reader: each non-empty line's fields, with what
follows a '#' dropped. Shared by the benchmark and MPI scripts."""


def poly_rows(path):
    rows = []
    with open(path) as f:
        for line in f:
            fields = line.split("#", 1)[0].split()
            if fields:
                rows.append(fields)
    return rows
