"""scripts/statistics_table.py: the docs' table of a statistical report, from its two CSVs (the
numbers as the report wrote them, levels coarse to fine, coupled columns only where present)."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

import statistics_table  # noqa: E402

LEVELS = """mesh,quantity,level,h_avg,runs,mean,mean low,mean high,CDF band +-,core-hours
"rcp","q",1,0.02,9,2.5,2.4,2.6,0.4,0.1
"rcp","q",0,0.04,10,3.25,3.2,3.3,0.4,0.01
"""
PAIRS = """mesh,quantity,h,h finer,KS D,p,detectable D,W1,W1 low,W1 high,mean change,mean change low,\
mean change high,pairs,E|D|,E|D| low,E|D| high,E|D|^2,E|D|^2 low,E|D|^2 high,Pr(|D| > eps),\
Pr(|D| > eps) low,Pr(|D| > eps) high,in distribution,of the mean,in mean,in probability
"rcp","q",0.04,0.02,0.5,0.0123456,0.6,0.75,0.5,1,-0.75,-1,-0.5,9,0.8,0.6,1,0.7,0.5,0.9,0.25,0.1,0.5,\
does not converge,undecided,converges,converging
"""


def test_a_row_per_quantity_with_the_reports_numbers(tmp_path):
    (tmp_path / "statistical-levels.csv").write_text(LEVELS)
    (tmp_path / "statistical-convergence.csv").write_text(PAIRS)
    lines = statistics_table.table(str(tmp_path), None).splitlines()
    assert len(lines) == 3
    assert "E\\|D\\|, the pairs" in lines[0]
    assert lines[2] == ("| q | 10, 9 | 3.25, 2.5 | 0.5 (0.012) | 0.75 | 0.8 | 0.25 | "
                        "does not converge | undecided | converges | converging |")
