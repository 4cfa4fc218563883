"""What the benchmark smoke tests' report checks share: collected failures, and a verdict at the end."""
import sys

errors = []


def check(condition, message):
    if not condition:
        errors.append(message)


def positive(obj, key, where):
    value = obj.get(key)
    check(isinstance(value, (int, float)) and value > 0, f"{where}: {key} = {value!r}, expected a positive number")


def finish(summary):
    if errors:
        print("FAILED:\n  " + "\n  ".join(errors))
        sys.exit(1)
    print(summary)
