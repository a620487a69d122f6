"""The demonstration study's data reconstruction (not part of the demid package).

``reconstruct`` rebuilds data/ccd/*.csv from the paper's published numbers;
``reconstruct_demo_data.py`` is its command line.  See data/README.md.
"""
