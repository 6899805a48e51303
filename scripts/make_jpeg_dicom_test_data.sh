#!/bin/bash
# Writes tests/data/dicom-phantom-jpeg: the Philips phantom's three slices
# (sample_data/dicom-ct-philips-phantom, BSD 2-Clause, Chris Rorden) with
# their pixel data recompressed losslessly, one codec per slice, as PACS
# exports send them:
#   I90  JPEG Lossless, process 14, first-order prediction (1.2.840.10008.1.2.4.70)
#   I100 JPEG-LS Lossless (1.2.840.10008.1.2.4.80)
#   I110 JPEG 2000 Lossless (1.2.840.10008.1.2.4.90)
# Needs gdcmconv (Debian package libgdcm-tools), which the build does not:
# the files are kept in the repository. Run from the repository's root.
set -euo pipefail
src=sample_data/dicom-ct-philips-phantom
out=tests/data/dicom-phantom-jpeg
mkdir -p "$out"
gdcmconv --jpeg "$src/I90" "$out/I90"
gdcmconv --jpegls "$src/I100" "$out/I100"
gdcmconv --j2k "$src/I110" "$out/I110"
cp "$src/LICENSE" "$out/LICENSE"
