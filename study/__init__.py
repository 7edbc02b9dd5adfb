"""poroseam work-precision studies (scripts/study, docs/studies.md): what an accuracy costs.

Modules: spec (reads and checks studies/<name>.toml), runs (option lists, the run cache,
poroseam through subprocess), measure (quantities of interest from a run's outputs and their
references), closed_forms (the named closed forms a study can use, built on analytic),
analytic (closed forms of Biot consolidation: Terzaghi, Mandel, a column with a permeable
joint; also used by the verification tests), report (study.csv, study.md, work_precision.png)."""
