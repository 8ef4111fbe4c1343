# SPDX-License-Identifier: GPL-3.0-or-later
"""cable view (doc/view.md) in a real browser: Debian's headless Chromium with
its software WebGL (SwiftShader) opens the page written for a small knot run
and for an atlas, clicks a point of the diagram, checks the values the page
shows against the C analysis and the canvas's pixels against the solution's
strands, moves the slider, and saves screenshots in tests/tmp/view/.

The test needs chromium, chromium-driver, python3-selenium and libjs-three
(scripts/install-deps.sh installs them); without a working WebGL it fails."""
import base64
import html
import io
import json
import os
import shutil
import subprocess

import numpy as np
import pytest

from conftest import BUILD, ROOT, copy_in, run_script

SHOTS = os.path.join(ROOT, 'tests', 'tmp', 'view')

# the flat (7,2) knot to its first branch point and the mode-1 branch from it
# to the paper's point (a) (T = -2.10752, the knot72 scene's run, shortened)
SCRIPT = """
flat = run(e='braid_knot', c='knot72', NMX=40, sv='flat')
bp = branch_points(flat, T=(0, 34), kind='double')[0]
m1 = run(bp, e='braid_knot_sym', c='knot72sym', UZR={'T': -2.10752}, STOP=['UZ1'], sv='mode1')
"""


@pytest.fixture(scope='module')
def rundir(tmp_path_factory):
    d = tmp_path_factory.mktemp('viewrun')
    copy_in(str(d), 'runs/knot72/c.knot72', 'runs/knot72/c.knot72sym')
    rc, out, err = run_script(d, SCRIPT)
    assert rc == 0, err
    return d


def cable_view(*args):
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    return subprocess.run([os.path.join(BUILD, 'cable'), 'view'] + list(args), capture_output=True, text=True,
                          env=env, timeout=600)


@pytest.fixture(scope='module')
def browser():
    webdriver = pytest.importorskip('selenium.webdriver')
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service
    o = Options()
    # SwiftShader: Chromium's software WebGL, no GPU needed (--use-gl=swiftshader
    # is gone from this Chromium; ANGLE's SwiftShader backend is the way)
    for a in ('--headless=new', '--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader',
              '--enable-unsafe-swiftshader', '--window-size=1400,1000', '--allow-file-access-from-files'):
        o.add_argument(a)
    d = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=o)
    d.set_script_timeout(30)
    yield d
    d.quit()


def open_page(browser, path):
    from selenium.webdriver.support.ui import WebDriverWait
    browser.get('file://' + str(path))
    WebDriverWait(browser, 30).until(lambda d: d.execute_script('return window.cableView && window.cableView.ready'))
    assert browser.execute_script('return window.cableView.error') is None
    # the 3-D view is a WebGL canvas
    assert browser.execute_script(
        "var c = document.getElementById('canvas3d'); return !!(c && c.getContext('webgl'));")


def canvas_pixels(browser):
    import matplotlib.image as mpimg
    url = browser.execute_script("return document.getElementById('canvas3d').toDataURL('image/png')")
    return mpimg.imread(io.BytesIO(base64.b64decode(url.split(',', 1)[1])), format='png')[:, :, :3]


def projected_hits(browser, img, pts):
    """Fraction of the world points pts [k, 3] that the page's camera puts on
    a drawn (not white background) pixel of the canvas."""
    m = np.array(browser.execute_script('return window.cableView.camera()')).reshape(4, 4).T
    h, w = img.shape[:2]
    x = np.c_[pts, np.ones(len(pts))] @ m.T
    ndc = x[:, :3] / x[:, 3:4]
    px = np.round((ndc[:, 0] + 1) / 2 * w - 0.5).astype(int)
    py = np.round((1 - ndc[:, 1]) / 2 * h - 0.5).astype(int)
    ok = (px >= 0) & (px < w) & (py >= 0) & (py < h)
    assert ok.all(), 'the solution leaves the canvas'
    drawn = img[py, px].min(axis=1) < 0.9
    return drawn.mean()


def strands(result, lab):
    from cable import _cable
    for b in result.branches:
        for i, l in enumerate(b.labels()):
            if l[0] == lab:
                st = _cable.strands(b, i)
                r1 = np.frombuffer(st['r1']).reshape(-1, 3)
                r2 = np.frombuffer(st['r2']).reshape(-1, 3)
                return r1, r2, _cable.analyze(b, i)
    raise KeyError(lab)


def test_run_page_in_chromium(rundir, browser, monkeypatch):
    import cable
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    os.makedirs(SHOTS, exist_ok=True)
    p = cable_view(str(rundir))
    assert p.returncode == 0, p.stderr
    page = os.path.join(str(rundir), 'view.html')
    text = open(page, encoding='utf-8').read()
    # offline: no address of anything outside the file
    assert 'src="http' not in text and "src='http" not in text and '<link' not in text
    open_page(browser, page)
    browser.save_screenshot(os.path.join(SHOTS, 'run_start.png'))

    monkeypatch.chdir(str(rundir))
    runner = cable.runner()
    flat, m1 = runner.loadbd('flat'), runner.loadbd('mode1')
    # one circle per labelled solution of the s-files
    circles = browser.find_elements(By.CSS_SELECTOR, '#diagram circle.pt')
    want = sorted([('flat', s.LAB) for s in flat()] + [('mode1', s.LAB) for s in m1()])
    names = browser.execute_script('return DATA.branches.map(function (b) { return b.name; })')
    got = sorted((names[int(c.get_attribute('data-branch'))], int(c.get_attribute('data-lab'))) for c in circles)
    assert got == want

    # click mode1's UZ1, the paper's point (a)
    uz = m1('UZ1')
    c = browser.find_element(By.CSS_SELECTOR, '#diagram circle.pt[data-lab="%d"][data-branch="%d"]'
                             % (uz.LAB, names.index('mode1')))
    c.click()
    info = browser.execute_script('return window.cableView.info')
    r1, r2, a = strands(m1, uz.LAB)
    assert info['branch'] == 'mode1' and info['lab'] == uz.LAB and info['ty'] == 'UZ'
    # the diagram's columns are float32: 7 significant digits (T, F: PAR(1),
    # PAR(16) of the braid problems; loadbd's solutions know no names)
    T, F = uz['PAR(1)'], uz['PAR(16)']
    assert abs(info['T'] - T) <= 1e-6 * abs(T) and abs(info['F'] - F) <= 1e-6 * F
    assert info['Lk'] == a['Lk'] and info['knot'] == a['knot'] and info['noverlap'] == a['noverlap']
    text = browser.find_element(By.ID, 'info').text
    assert 'LAB %d' % uz.LAB in text and a['knot'] in text
    assert ('do not overlap' in text) == (a['noverlap'] == 0)
    img = canvas_pixels(browser)
    browser.save_screenshot(os.path.join(SHOTS, 'run_uz1.png'))
    # the tubes are drawn where the page's camera puts this label's strands:
    # (nearly) every centre-line point lands on a drawn pixel, and the tubes
    # cover a fraction of the canvas, not all of it
    assert projected_hits(browser, img, np.r_[r1, r2]) > 0.97
    drawn = (img.min(axis=2) < 0.9).mean()
    assert 0.005 < drawn < 0.5
    # the slider: one step back along the branch shows the previous label
    labs = [s.LAB for s in m1()]
    k = labs.index(uz.LAB)
    slider = browser.find_element(By.ID, 'slider')
    assert int(slider.get_attribute('value')) == k and int(slider.get_attribute('max')) == len(labs) - 1
    slider.send_keys(Keys.ARROW_LEFT)
    info2 = browser.execute_script('return window.cableView.info')
    assert info2['lab'] == labs[k - 1]
    img2 = canvas_pixels(browser)
    q1, q2, a2 = strands(m1, labs[k - 1])
    assert info2['Lk'] == a2['Lk']
    assert projected_hits(browser, img2, np.r_[q1, q2]) > 0.97
    assert np.abs(img2 - img).max() > 0.2   # the picture changed
    browser.save_screenshot(os.path.join(SHOTS, 'run_slider.png'))
    # the braid axis on demand
    browser.find_element(By.ID, 'axis').click()
    assert browser.execute_script("return window.cableView.axisVisible()")
    # axis choice: L2-NORM on y redraws the diagram with that column
    from selenium.webdriver.support.ui import Select
    Select(browser.find_element(By.ID, 'ycol')).select_by_value('L2-NORM')
    assert 'L2-NORM' in browser.find_element(By.ID, 'diagram').text
    browser.save_screenshot(os.path.join(SHOTS, 'run_l2norm.png'))


def test_notebook_view_is_the_page(rundir, monkeypatch):
    """view(result)._repr_html_ is the page cable view writes (the same
    viewer and scripts) in an iframe, with the result's data."""
    import cable
    monkeypatch.chdir(str(rundir))
    m1 = cable.runner().loadbd('mode1')
    frame = m1._repr_html_()
    assert frame.startswith('<iframe') and 'srcdoc="' in frame
    inner = html.unescape(frame.split('srcdoc="', 1)[1].rsplit('"></iframe>', 1)[0])
    written = open(os.path.join(str(rundir), 'view.html'), encoding='utf-8').read()

    def outside_data(t):
        head, rest = t.split('<script>var DATA = ', 1)
        return head + rest.split('</script>', 1)[1]
    assert outside_data(inner) == outside_data(written)
    data = json.loads(inner.split('<script>var DATA = ', 1)[1].split(';\n</script>', 1)[0].replace('<\\/', '</'))
    assert [s['lab'] for s in data['branches'][0]['sols']] == [s.LAB for s in m1()]
    # a solution: its branch, with that label chosen
    uz = m1('UZ1')
    inner = html.unescape(uz._repr_html_().split('srcdoc="', 1)[1])
    assert '"select":%d' % uz.LAB in inner
    assert cable.view(m1, os.path.join(str(rundir), 'nb.html')).endswith('nb.html')


def test_atlas_page_in_chromium(rundir, browser, tmp_path):
    """An atlas: the page lists the tasks and opens each task's view; a task
    without its b./s. files says so."""
    from selenium.webdriver.common.by import By
    atl = tmp_path / 'atlas'
    t1 = atl / 'tasks' / 'knot7R-test-m1'
    t2 = atl / 'tasks' / 'knot9R-test-m1'
    t1.mkdir(parents=True)
    t2.mkdir(parents=True)
    for n in ('flat', 'mode1'):
        for k in 'bsd':
            shutil.copy(os.path.join(str(rundir), '%s.%s' % (k, n)), str(t1 / ('%s.%s' % (k, 'branch' if n == 'mode1' else n))))
    rows = [{'family': 'knot(7,2)', 'mode': 1, 'companion': 'trefoil', 'status': 'ok'}]
    (t1 / 'result.json').write_text(json.dumps({'name': t1.name, 'status': 'ok', 'rows': rows}))
    (t2 / 'result.json').write_text(json.dumps({'name': t2.name, 'status': 'ok', 'rows': rows + rows}))
    out = str(tmp_path / 'atlas.html')
    p = cable_view(str(atl), 'o=' + out)
    assert p.returncode == 0, p.stderr
    open_page(browser, out)
    trs = browser.find_elements(By.CSS_SELECTOR, '#tasks tr.task')
    assert len(trs) == 3   # the rows of both tasks
    assert browser.execute_script('return window.cableView.task') == t1.name
    assert len(browser.find_elements(By.CSS_SELECTOR, '#diagram circle.pt')) > 0
    trs[1].click()
    assert browser.execute_script('return window.cableView.task') == t2.name
    assert 'no b./s. files' in browser.find_element(By.ID, 'info').text
    trs[0].click()
    assert browser.execute_script('return window.cableView.task') == t1.name
    circles = browser.find_elements(By.CSS_SELECTOR, '#diagram circle.pt[data-ty="UZ"]')
    circles[0].click()
    assert browser.execute_script('return window.cableView.info.ty') == 'UZ'
    browser.save_screenshot(os.path.join(SHOTS, 'atlas.png'))


def test_committed_atlas_lists_every_task(browser, tmp_path):
    """The committed atlas (runs/atlas/atlas: result.json files, no b./s.
    files) gives a page listing every row of atlas.csv."""
    from selenium.webdriver.common.by import By
    src = os.path.join(ROOT, 'runs', 'atlas', 'atlas')
    out = str(tmp_path / 'atlas.html')
    p = cable_view(src, 'o=' + out)
    assert p.returncode == 0, p.stderr
    open_page(browser, out)
    with open(os.path.join(src, 'atlas.csv')) as f:
        nrows = sum(1 for _ in f) - 1
    assert len(browser.find_elements(By.CSS_SELECTOR, '#tasks tr.task')) == nrows


def test_view_errors(tmp_path):
    p = cable_view(str(tmp_path / 'nothing'))
    assert p.returncode != 0 and 'nothing: no such directory' in p.stderr
    p = cable_view(str(tmp_path))
    assert p.returncode != 0 and 'no b-files' in p.stderr
    p = cable_view(str(tmp_path), 'o=x.htm')
    assert p.returncode == 2 and 'must end in .html' in p.stderr
    assert os.listdir(str(tmp_path)) == []


def test_picture_captions(rundir, tmp_path, monkeypatch):
    """cable render and cable plot write a caption line (tEXt Description)
    that names what the picture shows; a filled mark on a branch point (the
    paper's numbering) replaces the AUTO labels of the branch points."""
    import cable
    import matplotlib.image as mpimg
    from cable import _cable
    from test_doc_img import png_caption
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    exe = os.path.join(BUILD, 'cable')
    out = str(tmp_path / 'r.png')
    p = subprocess.run([exe, 'render', 's.mode1', 'UZ1', 'o=' + out, 'color=pressure'], cwd=str(rundir),
                       capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stderr
    cap = png_caption(out)
    monkeypatch.chdir(str(rundir))
    runner = cable.Runner()
    uz = runner.loadbd('mode1')('UZ1')
    a = runner.analyze(uz)
    assert cap.startswith('cable render: label %d, T = %.8g' % (uz.LAB, uz['PAR(1)'])), cap
    assert 'Lk = %.4g, braid axis: %s' % (a['Lk'], a['knot']) in cap and '(coloured by contact pressure)' in cap
    plot = str(tmp_path / 'p.png')
    p = subprocess.run([exe, 'plot', 'b.flat', 'b.mode1', 'o=' + plot, 'title=two branches'], cwd=str(rundir),
                       capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stderr
    assert png_caption(plot) == ('two branches. cable plot: F against T; branches: flat, mode1; filled circles: '
                                 'branch points, triangles: folds, open circles: labelled points')
    bp = runner.loadbd('flat')('BP1')
    plain, numbered = str(tmp_path / 'a.png'), str(tmp_path / 'b.png')
    _cable.plot(plain, ['b.flat'], None, None, [], None)
    # a filled mark without text on BP1: the BPs keep their circles, their labels go
    _cable.plot(numbered, ['b.flat'], None, None, [(bp['PAR(1)'], bp['PAR(16)'], '', True)], None)
    x, y = mpimg.imread(plain)[:, :, :3], mpimg.imread(numbered)[:, :, :3]
    # the labels are dark text: the numbered diagram has fewer dark pixels
    assert (y.max(axis=2) < 0.3).sum() < (x.max(axis=2) < 0.3).sum()
