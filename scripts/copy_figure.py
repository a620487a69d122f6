"""Snakemake script: a material's figure (PNG and SVG) copied byte for byte under the paper's figure name."""

from demid.io import copy_files

inputs, outputs = snakemake.input, snakemake.output  # noqa: F821
copy_files({inputs.figure: outputs.figure, inputs.figure_svg: outputs.figure_svg}, snakemake.log[0])  # noqa: F821
