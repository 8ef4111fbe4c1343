# SPDX-License-Identifier: GPL-3.0-or-later
"""A screenshot of a `cable view` page in headless Chromium (software WebGL):
    view_screenshot.py PAGE.html OUT.png [BRANCH]
The page opens at its first UZ point, or at BRANCH's first UZ point when
given (the knot72 scene: mode2, the paper's (b)); prints the page's load time (navigation start to
the viewer ready, performance.now())."""
import os
import sys

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait


def browser(width=1400, height=840):
    o = Options()
    for a in ('--headless=new', '--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader',
              '--enable-unsafe-swiftshader', '--window-size=%d,%d' % (width, height), '--hide-scrollbars'):
        o.add_argument(a)
    return webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=o)


def main(argv):
    page, out = argv[0], argv[1]
    d = browser()
    try:
        d.get('file://' + os.path.abspath(page))
        WebDriverWait(d, 60).until(lambda x: x.execute_script('return window.cableView && window.cableView.ready'))
        err = d.execute_script('return window.cableView.error')
        if err:
            print('view_screenshot: %s' % err, file=sys.stderr)
            return 1
        if len(argv) >= 3:
            ok = d.execute_script(
                'var name = arguments[0];'
                'var b = DATA.branches.findIndex(function (x) { return x.name === name; });'
                'if (b < 0) return false;'
                'var s = DATA.branches[b].sols.findIndex(function (x) { return x.ty === "UZ"; });'
                'if (s < 0) return false; window.cableView.select(b, s); return true;', argv[2])
            if not ok:
                print('view_screenshot: no UZ point on branch %s' % argv[2], file=sys.stderr)
                return 1
        print('view_screenshot: %s ready %.0f ms after navigation start' % (
            page, d.execute_script('return window.cableView.readyAt')))
        d.save_screenshot(out)
    finally:
        d.quit()
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
