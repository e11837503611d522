"""Wall loads from sluice's results folders: the package behind `scripts/loads`.

signals   moving averages, integrals and threshold stretches on irregular samples
impact    scales (rho g H, sqrt(H/g)), the first-impact window and its figures
runs      a results folder: probes, summary.json, the case file, dx and scales
figures   one load probe's figures in SI and scaled units
ensemble  statistics over the runs of a jitter ensemble
gci       three-resolution grid convergence index (Roache 1998; Celik et al. 2008)
tables    text and CSV tables

The tests are in tests/ beside this file: python3 -m unittest discover scripts/sluice_loads/tests
"""
