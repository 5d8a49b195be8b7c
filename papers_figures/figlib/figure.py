"""What a figure module declares (FIGURE) and what draw() receives (Context)."""
import json
import os
from dataclasses import dataclass, field as dc_field

import numpy as np

from .field import Field

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SKELETONS = os.path.join(HERE, "skeletons")


@dataclass
class Figure:
    paper: str                 # "Hubert 2012" or "Zanni et al. 2013" (or another paper's short name)
    kind: str                  # "Figure" or "Table"
    number: str                # "5", "4c", ...
    caption: str               # the paper's caption, in English
    skeletons: list = dc_field(default_factory=list)   # files in papers_figures/skeletons/
    kernel: str = ""           # kernel(s) and parameters, as the gallery prints them
    iso: str = ""              # the level(s) drawn
    view: str = ""             # the plane / range shown
    size: tuple = (640, 480)   # image size in pixels (width, height); None for a table without image
    original_caption: str = "" # the caption in the paper's language, when it is not English
    section: str = ""          # what part of the paper's figure we draw, if not all of it
    experiment: bool = False   # this project's own experiment, not a figure printed in a paper: the gallery
                               # lists it under "Experiments" and its claims as goals, not as the paper's word

    @property
    def heading(self):
        if self.experiment:
            return f"Experiment: {self.paper}, {self.number}"
        return f"{self.paper}, {self.kind} {self.number}"


@dataclass
class Context:
    skelconv: str
    quick: bool
    image_path: str            # where draw() writes its PNG (None in --no-images runs)
    log: object = print
    markdown: str = ""         # extra markdown (tables) draw() wants in the gallery

    def res(self, full, quick):
        """A resolution (grid size, sample count): `quick` for ctest, `full` for the gallery."""
        return quick if self.quick else full

    def field(self, name):
        """The Field of papers_figures/skeletons/NAME."""
        return Field.from_file(self.skelconv, os.path.join(SKELETONS, name))

    def field_of(self, primitives):
        return Field(self.skelconv, {"primitives": list(primitives)})


def load_skeleton(name):
    with open(os.path.join(SKELETONS, name)) as handle:
        return json.load(handle)


def scaled_primitives(primitives, alpha):
    """Every point and radius of SCALIS/classical primitives scaled by alpha
    (weights and kernel parameters left alone: the caller decides those)."""
    out = []
    for p in primitives:
        q = json.loads(json.dumps(p))
        for key in ("a", "b"):
            if key in q:
                q[key] = list(np.asarray(q[key], dtype=float) * alpha)
        if "vertices" in q:
            q["vertices"] = [list(np.asarray(v, dtype=float) * alpha) for v in q["vertices"]]
        if "radius" in q:
            q["radius"] = [r * alpha for r in q["radius"]]
        out.append(q)
    return out
