"""figlib: the shared machinery of papers_figures/ (see docs/figures.md).

A figure is one module in papers_figures/figures/ that defines
  FIGURE = Figure(...)      what it reproduces (paper, number, caption, view)
  def draw(ctx) -> list[Claim]   draws ctx.image_path and checks the claims
and is registered by one line in papers_figures/figures.txt.
"""
