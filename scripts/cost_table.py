#!/usr/bin/env python3
"""scripts/cost_table.py CSV MARKDOWN - the summary table of `cdref report --csv` in a page.

Reads the report's CSV (docs/cost-report.csv) and replaces the lines between
<!-- cost-table begin --> and <!-- cost-table end --> in MARKDOWN (docs/cost.md) with one row
per query: ns a query and the ratio to `bare` of the main rows, and the book's and the robust
tier's misclassified share of the hard families at double. scripts/report.sh runs it.
"""
import csv
import sys

COLUMNS = [
    ("bare (book at double, unchecked)", "`bare`"),
    ("book double", "book double"),
    ("stable double", "stable double"),
    ("robust double, certified classification", "robust double, classification"),
    ("robust double", "robust double, every output"),
    ("oracle, classification", "oracle, classification"),
    ("oracle, every output rounded", "oracle, every output"),
    ("book at Gmpq", "book at `Gmpq`"),
]


def cell(row):
    if row is None:
        return ""
    ns, ratio = float(row["ns_per_query"]), float(row["ratio_to_bare"])
    t = ("%.0f" % ns) if ns >= 100 else ("%.1f" % ns)
    r = ("%.3g" % ratio) if ratio < 1000 else ("%.0f" % ratio)
    return t if row["implementation"].startswith("bare") else "%s (%sx)" % (t, r)


def share(row):
    if row is None:
        return ""
    try:
        return "%.3g%%" % (100 * float(row["misclassified_hard"]))
    except ValueError:
        return row["misclassified_hard"]


def table(rows):
    by = {}
    for r in rows:
        by.setdefault(r["query"], {})[r["implementation"]] = r
    head = ["query"] + [c[1] for c in COLUMNS] + ["misclassified, hard families: book double / robust double"]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for q, impl in by.items():
        cells = [cell(impl.get(k)) for k, _ in COLUMNS]
        mis = "%s / %s" % (share(impl.get("book double")), share(impl.get("robust double")))
        out.append("| " + " | ".join(["`%s`" % q] + cells + [mis]) + " |")
    return out


def main():
    src, page = sys.argv[1], sys.argv[2]
    with open(src, newline="") as f:
        rows = list(csv.DictReader(f))
    lines = open(page).read().split("\n")
    b = lines.index("<!-- cost-table begin -->")
    e = lines.index("<!-- cost-table end -->")
    lines[b + 1:e] = table(rows)
    with open(page + ".tmp", "w") as f:
        f.write("\n".join(lines))
    import os
    os.replace(page + ".tmp", page)


if __name__ == "__main__":
    main()
