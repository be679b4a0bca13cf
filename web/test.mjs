// The page in a real browser: headless Chromium driven over the DevTools protocol on a pipe
// (no driver library, no port), against the page served from target/web by a local static
// server. Every reconstruction the page shows is compared with the command line's on the
// same points and options: the summary's counts, and the JSON, SVG and GeoJSON text itself.
//
//   node web/test.mjs URL   (web/test.sh starts the server and passes its URL)
//
// Environment: CHROMIUM (default /usr/bin/chromium), WDM_CRUST (default
// target/release/wdm-crust), WEB_TEST_OUT (default target/web-test: screenshots, points).

import { spawn, execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

const base = process.argv[2];
if (!base) {
  console.error('usage: node web/test.mjs URL-of-the-served-target/web/');
  process.exit(2);
}
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const cli = process.env.WDM_CRUST || 'target/release/wdm-crust';
const out = path.resolve(process.env.WEB_TEST_OUT || 'target/web-test');
fs.rmSync(out, { recursive: true, force: true });
fs.mkdirSync(out, { recursive: true });

// ---- the browser -------------------------------------------------------------------------

class Browser {
  constructor() {
    this.process = spawn(chromium, [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-dev-shm-usage', '--hide-scrollbars', '--mute-audio',
      `--user-data-dir=${path.join(out, 'profile')}`, '--remote-debugging-pipe', 'about:blank',
    ], { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
    this.stderr = '';
    this.process.stderr.on('data', (chunk) => { this.stderr += chunk; });
    this.next = 1;
    this.waiting = new Map();
    this.listeners = [];
    let buffered = '';
    this.process.stdio[4].on('data', (chunk) => {
      buffered += chunk.toString('utf8');
      let end;
      while ((end = buffered.indexOf('\0')) >= 0) {
        const message = JSON.parse(buffered.slice(0, end));
        buffered = buffered.slice(end + 1);
        if (message.id && this.waiting.has(message.id)) {
          const { resolve, reject, method } = this.waiting.get(message.id);
          this.waiting.delete(message.id);
          if (message.error) reject(new Error(`${method}: ${message.error.message}`));
          else resolve(message.result);
        } else {
          for (const listener of this.listeners) listener(message);
        }
      }
    });
    this.exited = new Promise((resolve) => this.process.on('exit', resolve));
  }

  send(method, params = {}, sessionId = undefined) {
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.waiting.set(id, { resolve, reject, method });
      this.process.stdio[3].write(`${JSON.stringify({ id, method, params, sessionId })}\0`);
    });
  }

  async page(width, height) {
    const { targetId } = await this.send('Target.createTarget', { url: 'about:blank' });
    const { sessionId } = await this.send('Target.attachToTarget', { targetId, flatten: true });
    const page = new Page(this, sessionId);
    await page.send('Page.enable');
    await page.send('Runtime.enable');
    await page.send('Emulation.setDeviceMetricsOverride', { width, height, deviceScaleFactor: 1, mobile: false });
    return page;
  }

  async close() {
    await this.send('Browser.close').catch(() => {});
    await Promise.race([this.exited, sleep(5000)]);
    this.process.kill();
  }
}

class Page {
  constructor(browser, sessionId) {
    this.browser = browser;
    this.sessionId = sessionId;
    this.problems = [];
    browser.listeners.push((message) => {
      if (message.sessionId !== sessionId) return;
      if (message.method === 'Runtime.exceptionThrown') {
        this.problems.push(`exception: ${message.params.exceptionDetails.exception?.description || message.params.exceptionDetails.text}`);
      } else if (message.method === 'Runtime.consoleAPICalled' && message.params.type === 'error') {
        this.problems.push(`console.error: ${message.params.args.map((a) => a.value ?? a.description).join(' ')}`);
      }
    });
  }

  send(method, params = {}) {
    return this.browser.send(method, params, this.sessionId);
  }

  async evaluate(expression) {
    const { result, exceptionDetails } = await this.send('Runtime.evaluate', {
      expression, awaitPromise: true, returnByValue: true,
    });
    if (exceptionDetails) {
      throw new Error(`${expression}: ${exceptionDetails.exception?.description || exceptionDetails.text}`);
    }
    return result.value;
  }

  async waitFor(expression, what, timeout = 60000) {
    const start = Date.now();
    for (;;) {
      const value = await this.evaluate(expression).catch(() => undefined);
      if (value) return value;
      if (Date.now() - start > timeout) {
        const now = await this.evaluate("[document.getElementById('summary').textContent, document.getElementById('progress').textContent]").catch((e) => e.message);
        throw new Error(`timed out waiting for ${what}; the summary and progress say ${JSON.stringify(now)}`);
      }
      await sleep(50);
    }
  }

  async open(query) {
    await this.send('Page.navigate', { url: `${base}${query}` });
    await this.waitFor("document.readyState === 'complete' && window.wdmPage !== undefined", 'the page');
  }

  // Waits until the summary shows a result after `runs` (the count before an action), of
  // the points as they are (a pointer move reaches the page at its next frame).
  async settled(runs = 0, timeout = 60000) {
    await this.waitFor(
      `(() => { const s = document.getElementById('summary').dataset;
        return (s.state === 'done' && Number(s.runs) > ${runs} && window.wdmPage.idle()) || s.state === 'error'; })()`,
      'the result', timeout,
    );
    return this.state();
  }

  state() {
    return this.evaluate(`(() => {
      const s = document.getElementById('summary');
      return { state: s.dataset.state, runs: Number(s.dataset.runs || 0), points: Number(s.dataset.points || 0),
               text: s.textContent, counts: s.querySelector('.counts')?.textContent ?? null };
    })()`);
  }

  async screenshot(name) {
    const { data } = await this.send('Page.captureScreenshot', { format: 'png' });
    const file = path.join(out, `${name}.png`);
    fs.writeFileSync(file, Buffer.from(data, 'base64'));
    return file;
  }

  async chooseFile(selector, file) {
    const { root } = await this.send('DOM.getDocument');
    const { nodeId } = await this.send('DOM.querySelector', { nodeId: root.nodeId, selector });
    await this.send('DOM.setFileInputFiles', { nodeId, files: [path.resolve(file)] });
  }

  async mouse(type, x, y) {
    await this.send('Input.dispatchMouseEvent', {
      type, x, y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1,
    });
  }
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// ---- the command line --------------------------------------------------------------------

function commandLine(file, args = [], format = 'json') {
  return execFileSync(cli, ['reconstruct', file, '--format', format, '--quiet', ...args], {
    encoding: 'utf8', maxBuffer: 1 << 28, stdio: ['ignore', 'pipe', 'pipe'],
  });
}

const counted = (n, one, many) => (n === 1 ? `1 ${one}` : `${n} ${many}`);

// The command line's summary line's counts, from its JSON.
function countsOf(json) {
  const closed = json.curves.filter((c) => c.closed).length;
  return [
    counted(closed, 'closed curve', 'closed curves'),
    counted(json.curves.length - closed, 'open chain', 'open chains'),
    counted(json.unassigned.length, 'point on no curve', 'points on no curve'),
    counted(json.duplicates.length, 'duplicate', 'duplicates'),
  ].join(', ');
}

// The page's points in a file the command line reads back exactly (JavaScript prints the
// shortest decimal that reads back as the same double).
async function pagePoints(page, name) {
  const coords = await page.evaluate('Array.from(window.wdmPage.points())');
  const lines = [];
  for (let i = 0; i < coords.length; i += 2) lines.push(`${coords[i]} ${coords[i + 1]}`);
  const file = path.join(out, name);
  fs.writeFileSync(file, `${lines.join('\n')}\n`);
  return file;
}

// ---- the checks --------------------------------------------------------------------------

const results = [];
async function check(name, body) {
  try {
    await body();
    results.push([name, null]);
    console.log(`ok - ${name}`);
  } catch (e) {
    results.push([name, e]);
    console.log(`FAIL - ${name}: ${e.message}`);
  }
}

function equal(actual, expected, what) {
  if (actual !== expected) {
    const at = [...actual].findIndex((c, i) => c !== expected[i]);
    throw new Error(`${what}: differ (lengths ${actual.length} and ${expected.length}, first at ${at}: `
      + `${JSON.stringify(actual.slice(Math.max(0, at - 40), at + 40))} vs ${JSON.stringify(expected.slice(Math.max(0, at - 40), at + 40))})`);
  }
}

// The page's downloads of what it shows, against the command line on the same file.
async function sameAsCommandLine(page, file, args) {
  equal((await page.evaluate("window.wdmPage.exportText('json')")).trimEnd(), commandLine(file, args).trimEnd(), `JSON of ${file} ${args.join(' ')}`);
}

// How many doubles lie between a and b (0: the same number).
function ulps(a, b) {
  const bits = (x) => {
    const view = new DataView(new ArrayBuffer(8));
    view.setFloat64(0, x);
    const i = view.getBigInt64(0);
    return i < 0n ? -(i & 0x7fffffffffffffffn) : i;
  };
  const d = bits(a) - bits(b);
  return Number(d < 0n ? -d : d);
}

// The fitted coordinates of smoothing are rounded values, computed with `hypot` among
// others, which the browser's build takes from Rust's portable libm and the native one from
// the system's: they may differ in the last bits. Everything else must be equal; those
// within `most` ulps.
async function sameUpToFittedCoords(page, file, args, most) {
  const shown = JSON.parse(await page.evaluate("window.wdmPage.exportText('json')"));
  const expected = JSON.parse(commandLine(file, args));
  let worst = 0;
  let differing = 0;
  let total = 0;
  shown.curves.forEach((curve, c) => {
    curve.coords.forEach((p, k) => {
      for (const axis of [0, 1]) {
        const d = ulps(p[axis], expected.curves[c].coords[k][axis]);
        worst = Math.max(worst, d);
        differing += d > 0 ? 1 : 0;
        total += 1;
      }
    });
    delete curve.coords;
    delete expected.curves[c].coords;
  });
  equal(JSON.stringify(shown), JSON.stringify(expected), `JSON of ${file} ${args.join(' ')} without the fitted coordinates`);
  console.log(`  fitted coordinates: ${differing} of ${total} differ, by at most ${worst} ulps`);
  if (worst > most) throw new Error(`fitted coordinates differ by ${worst} ulps (at most ${most} expected)`);
}

const examples = [
  ['bean', 'examples/data/bean.txt'],
  ['mushroom', 'examples/data/mushroom.p2d'],
  ['crocodile', 'examples/data/crocodile-conf.p2d'],
  ['ventilator', 'tests/data/hnn-crust-sgp16/ventilator.p2d'],
  ['apple', 'examples/data/apple_2percent_noise.txt'],
  ['circle', 'examples/data/Circle0.txt'],
  ['stair', 'tests/data/stretchdenoise/data/stair.xy'],
  ['family', 'tests/data/stretchdenoise/data/family.p2d'],
];

const browser = new Browser();
let page;
try {
  page = await browser.page(1280, 800);

  await check("the bean example's summary says the command line's counts", async () => {
    await page.open('?example=bean');
    const shown = await page.settled();
    const json = JSON.parse(commandLine('examples/data/bean.txt'));
    const counts = countsOf(json);
    if (!shown.counts || !shown.counts.startsWith(`${counts}. `)) {
      throw new Error(`#summary says ${JSON.stringify(shown.text)}, the command line ${JSON.stringify(counts)}`);
    }
    if (!shown.counts.startsWith('1 closed curve, 0 open chains, 0 points on no curve')) {
      throw new Error(`the bean is one closed curve through every point: ${shown.counts}`);
    }
    await page.screenshot('bean');
  });

  for (const [name, file] of examples) {
    await check(`example ${name}: the page's JSON is the command line's`, async () => {
      await page.open(`?example=${name}`);
      const shown = await page.settled(0, 120000);
      if (shown.state !== 'done') throw new Error(shown.text);
      await sameAsCommandLine(page, file, []);
      if (!shown.counts.startsWith(`${countsOf(JSON.parse(commandLine(file)))}. `)) throw new Error(shown.counts);
      await page.screenshot(`example-${name}`);
    });
  }

  const variants = [
    ['bean', 'examples/data/bean.txt', '&algorithm=crust', ['--algorithm', 'crust']],
    ['bean', 'examples/data/bean.txt', '&algorithm=nn-crust', ['--algorithm', 'nn-crust']],
    ['ventilator', 'tests/data/hnn-crust-sgp16/ventilator.p2d', '&no-peeling=1&medial-axis=none', ['--no-peeling', '--medial-axis', 'none']],
    ['apple', 'examples/data/apple_2percent_noise.txt', '&no-thinning=1', ['--no-thinning']],
  ];
  for (const [name, file, query, args] of variants) {
    await check(`example ${name} with ${args.join(' ')}: the page's JSON is the command line's`, async () => {
      await page.open(`?example=${name}${query}`);
      const shown = await page.settled();
      if (shown.state !== 'done') throw new Error(shown.text);
      await sameAsCommandLine(page, file, args);
    });
  }

  await check("example apple with --smooth --medial-axis raw: the page's JSON is the command line's, the fitted coordinates to a few ulps", async () => {
    await page.open('?example=apple&smooth=1&medial-axis=raw');
    const shown = await page.settled();
    if (shown.state !== 'done') throw new Error(shown.text);
    await sameUpToFittedCoords(page, 'examples/data/apple_2percent_noise.txt', ['--smooth', '--medial-axis', 'raw'], 16);
  });

  await check("the downloads are the command line's SVG (with the layers shown) and GeoJSON", async () => {
    await page.open('?example=apple&show=delaunay,voronoi,labels');
    await page.settled();
    const file = 'examples/data/apple_2percent_noise.txt';
    const svg = await page.evaluate("window.wdmPage.exportText('svg')");
    equal(svg, commandLine(file, ['--show', 'delaunay,voronoi,labels'], 'svg'), 'SVG');
    equal(await page.evaluate("window.wdmPage.exportText('geojson')"), commandLine(file, [], 'geojson'), 'GeoJSON');
    await page.screenshot('apple-layers');
  });

  await check('a point file opened through the file input is reconstructed as on the command line', async () => {
    await page.open('?example=bean');
    const before = await page.settled();
    const file = 'tests/data/fitconnect/data/Cup0.txt';
    await page.chooseFile('#file', file);
    const shown = await page.settled(before.runs);
    if (shown.state !== 'done' || shown.points !== 263) throw new Error(`${shown.points} points: ${shown.text}`);
    await sameAsCommandLine(page, file, []);
  });

  await check('a point file dropped on the picture is reconstructed as on the command line', async () => {
    await page.open('?example=bean');
    const before = await page.settled();
    const file = 'examples/data/mushroom.p2d';
    const box = await page.evaluate("(() => { const r = document.getElementById('canvas').getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()");
    const data = { items: [], files: [path.resolve(file)], dragOperationsMask: 1 };
    for (const type of ['dragEnter', 'dragOver', 'drop']) {
      await page.send('Input.dispatchDragEvent', { type, x: box[0], y: box[1], data });
    }
    const shown = await page.settled(before.runs);
    if (shown.state !== 'done' || shown.points !== 59) throw new Error(`${shown.points} points: ${shown.text}`);
    await sameAsCommandLine(page, file, []);
  });

  await check("a bad file shows the parser's message, naming the line", async () => {
    const bad = path.join(out, 'bad.txt');
    fs.writeFileSync(bad, '1 2\n3 four\n5 6\n');
    let message = '';
    try {
      commandLine(bad);
    } catch (e) {
      message = e.stderr.trim();
    }
    // The command line says `<path>:2: <problem>`; the page `bad.txt: line 2: <problem>`.
    const problem = message.match(/bad\.txt:2: (.*)$/)?.[1];
    if (!problem) throw new Error(`the command line said ${JSON.stringify(message)}`);
    await page.open('?example=bean');
    await page.settled();
    await page.chooseFile('#file', bad);
    await page.waitFor("document.getElementById('summary').dataset.state === 'error'", 'the error');
    const shown = await page.state();
    equal(shown.text, `bad.txt: line 2: ${problem}`, 'the message');
    await page.screenshot('bad-file');
  });

  await check('a click adds a point, and the result is the command line on the new points', async () => {
    await page.open('?example=bean');
    const before = await page.settled();
    const box = await page.evaluate("(() => { const r = document.getElementById('canvas').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; })()");
    const [x, y] = [box[0] + box[2] / 2, box[1] + box[3] / 2];
    await page.mouse('mousePressed', x, y);
    await page.mouse('mouseReleased', x, y);
    const shown = await page.settled(before.runs);
    if (shown.points !== 151) throw new Error(`${shown.points} points after the click: ${shown.text}`);
    await sameAsCommandLine(page, await pagePoints(page, 'clicked.txt'), []);
  });

  await check('from no point to three by clicks, every layer on: each result the command line\'s', async () => {
    await page.open('?example=bean&show=delaunay,voronoi,labels');
    let before = await page.settled();
    await page.evaluate("document.getElementById('clear').click()");
    let shown = await page.settled(before.runs);
    if (!shown.counts?.startsWith('0 closed curves, 0 open chains, 0 points on no curve, 0 duplicates. 0 points')) throw new Error(shown.text);
    const box = await page.evaluate("(() => { const r = document.getElementById('canvas').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; })()");
    for (const [u, v] of [[0.3, 0.3], [0.7, 0.4], [0.5, 0.8]]) {
      before = shown;
      const [x, y] = [box[0] + u * box[2], box[1] + v * box[3]];
      await page.mouse('mousePressed', x, y);
      await page.mouse('mouseReleased', x, y);
      shown = await page.settled(before.runs);
      if (shown.state !== 'done') throw new Error(shown.text);
      await sameAsCommandLine(page, await pagePoints(page, `clicked-${shown.points}.txt`), []);
    }
    if (shown.points !== 3) throw new Error(shown.text);
  });

  await check('dragging a point moves it, and the result is the command line on the moved points', async () => {
    await page.open('?example=bean');
    const before = await page.settled();
    // After the layout of the result's frame, where the points are drawn.
    await page.evaluate('new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))');
    const [x, y] = await page.evaluate('window.wdmPage.screenOf(0)');
    const [x0, y0] = await page.evaluate('Array.from(window.wdmPage.points().slice(0, 2))');
    await page.mouse('mousePressed', x, y);
    for (let step = 1; step <= 10; step += 1) {
      await page.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: x + 4 * step, y: y + 3 * step, button: 'left', buttons: 1 });
      await sleep(20);
    }
    await page.mouse('mouseReleased', x + 40, y + 30);
    // The result of the last position follows those of the positions on the way.
    const shown = await page.settled(before.runs);
    const [x1, y1] = await page.evaluate('Array.from(window.wdmPage.points().slice(0, 2))');
    if (shown.points !== 150 || (x1 === x0 && y1 === y0)) throw new Error(`point 0 at ${x1}, ${y1}: ${shown.text}`);
    await sameAsCommandLine(page, await pagePoints(page, 'dragged.txt'), []);
    await page.screenshot('bean-dragged');
  });

  await check('the largest example reconstructs in the page, with the layers drawn', async () => {
    await page.open('?example=family&show=delaunay');
    const shown = await page.settled(0, 120000);
    if (shown.state !== 'done' || shown.points !== 9990) throw new Error(shown.text);
    const ms = await page.evaluate("document.querySelector('#summary .note').textContent");
    console.log(`  family (9990 points): ${ms.trim()} in the page`);
    await page.screenshot('family');
  });

  await check('a large file shows progress, the page answering meanwhile, and ends as on the command line', async () => {
    // 200 000 samples of a wavy closed curve, a little jittered, in a scrambled order.
    const n = 200000;
    let seed = 12345;
    const next = () => {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      return seed / 2147483648;
    };
    const lines = [];
    for (let k = 0; k < n; k += 1) {
      const t = ((k * 7919) % n) / n * 2 * Math.PI;
      const r = 1 + 0.15 * Math.sin(5 * t) + 2e-6 * (next() - 0.5);
      lines.push(`${r * Math.cos(t)} ${r * Math.sin(t)}`);
    }
    const big = path.join(out, 'large.txt');
    fs.writeFileSync(big, `${lines.join('\n')}\n`);
    await page.open('?example=bean');
    const before = await page.settled();
    await page.chooseFile('#file', big);
    await page.waitFor("!document.getElementById('progress').hidden && document.getElementById('progress').textContent.includes('reconstructing')", 'the progress box');
    // The page answers while the engine runs: the answers that came during the run.
    let slowest = 0;
    let answered = 0;
    let seen = '';
    for (;;) {
      const start = Date.now();
      const state = await page.evaluate("[document.getElementById('summary').dataset.state, document.getElementById('progress').textContent]");
      slowest = Math.max(slowest, Date.now() - start);
      if (state[0] !== 'working') break;
      answered += 1;
      seen = state[1];
      await sleep(50);
    }
    const shown = await page.settled(before.runs, 300000);
    console.log(`  ${n} points: ${shown.text.match(/\((\d+ ms)\)/)?.[1]} in the page; it answered ${answered} times during the run, `
      + `the slowest answer (the result drawn) in ${slowest} ms; last progress: ${JSON.stringify(seen)}`);
    if (shown.points !== n) throw new Error(shown.text);
    if (answered < 3) throw new Error(`the page answered only ${answered} times during the run`);
    if (!/triangulate \d+ ms/.test(seen)) throw new Error(`no phase in the progress box: ${JSON.stringify(seen)}`);
    await sameAsCommandLine(page, big, []);
    await page.screenshot('large');
  });

  await check('the picture for the README (docs/web-page.png is a copy of target/web-test/page.png)', async () => {
    const small = await browser.page(1000, 600);
    await small.open('?example=bean&show=voronoi,labels');
    const shown = await small.settled();
    if (shown.state !== 'done') throw new Error(shown.text);
    await small.screenshot('page');
    page.problems.push(...small.problems);
  });

  if (page.problems.length > 0) {
    results.push(['no error in the console', new Error(page.problems.join('; '))]);
    console.log(`FAIL - no error in the console: ${page.problems.join('; ')}`);
  }
} finally {
  await browser.close();
}

const failed = results.filter(([, e]) => e).length;
console.log(`${results.length - failed} passed, ${failed} failed`);
console.log(`screenshots in ${out}`);
process.exit(failed === 0 ? 0 : 1);
