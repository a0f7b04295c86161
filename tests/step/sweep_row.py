"""One row's middle columns for .ci/step-sweep.sh from a `convert --report` JSON: the
number of objects, and the object with the largest measured deviation relative to its
tolerance (deviation / tolerance, and the forms present)."""
import json
import sys

items = json.load(open(sys.argv[1]))["items"]
worst = max(items, key=lambda i: i["max_deviation"] / i["tolerance"])
forms = ", ".join(sorted({i["form"] for i in items}))
print(f"{len(items)} | {worst['max_deviation']:.2e} / {worst['tolerance']:.2e} ({forms})")
