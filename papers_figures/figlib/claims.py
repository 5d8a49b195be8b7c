"""A checked claim: what the paper says, what we measured, and whether the
measurement supports it.

`agrees` is decided by the figure's own test (a threshold stated in the
figure file). `expect_agreement=False` marks a known disagreement with the
paper (a misprint, or a claim our numbers contradict): the gallery says so,
and ctest then asserts the disagreement, so that a change is noticed either way.
"""
from dataclasses import dataclass


@dataclass
class Claim:
    statement: str          # the paper's claim, in a sentence
    measured: str           # our numbers, formatted
    agrees: bool            # does the measurement support the statement?
    expect_agreement: bool = True
    note: str = ""          # e.g. the misprint or why we disagree

    def __post_init__(self):
        self.agrees = bool(self.agrees)   # numpy booleans are not JSON

    @property
    def as_expected(self):
        return self.agrees == self.expect_agreement


def fmt(x, digits=3):
    """A number for the gallery: %.{digits}g, with 0 as 0."""
    return "0" if x == 0 else f"{x:.{digits}g}"
