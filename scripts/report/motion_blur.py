"""motion_blur's report section: the equal-time comparison (scripts/report/accumulation_report.py)."""
import importlib.util
import pathlib

_spec = importlib.util.spec_from_file_location("accumulation_report", pathlib.Path(__file__).with_name("accumulation_report.py"))
_shared = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_shared)


def extra(rows, out_dir):
    return _shared.equal_time(rows) + _shared.equal_time(rows, key="ms_min")
