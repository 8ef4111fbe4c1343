#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make doc-img: the README's pictures (doc/img) regenerated from the knot72
# scene: replay it, copy its diagram and renders, write its `cable view`
# page and a screenshot of that page (headless Chromium).
# tests/python/test_doc_img.py checks that doc/img holds what this makes.
set -euo pipefail
cd "$(dirname "$0")/.."
./cable replay runs/knot72/knot72.auto
cp runs/knot72/knot72.png runs/knot72/knot72_b.png runs/knot72/knot72_d.png runs/knot72/knot72_mirror.png doc/img/
./cable view runs/knot72
PYTHONPATH=build/release/python /usr/bin/python3 scripts/view_screenshot.py runs/knot72/view.html doc/img/view.png mode2
echo "doc-img: doc/img/knot72.png knot72_b.png knot72_d.png knot72_mirror.png view.png written"
