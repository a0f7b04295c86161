"""The judges' common tally: run each case, print one line per result ('ok   …' or
'FAIL …') and 'N passed, M failed'; a case that raises RuntimeError is one failure."""


def tally(cases):
    """`cases`: (label, thunk) pairs, each thunk returning [(ok, line), ...]. Returns the
    exit status (1 on any failure)."""
    passed = failed = 0
    for label, run in cases:
        try:
            results = run()
        except RuntimeError as e:
            results = [(False, f"{label}: {e}" if label else str(e))]
        for ok, line in results:
            print(("ok   " if ok else "FAIL ") + line)
            passed += ok
            failed += not ok
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0
