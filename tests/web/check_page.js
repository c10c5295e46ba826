// Drives the browser build in headless Chromium (puppeteer-core); run by tests/web/web_test.sh.
//   node check_page.js --url URL --modules NODE_MODULES --native NATIVE.json --native-idle IDLE.json
//                      --out DIR REPLAY...
// Checks, each printed as PASS or FAIL:
//  1. ?level=levels/01-first-roll.json&frames=300&press=right:0-299 ends with the native summary's
//     player position, bit for bit, and the page then shows a picture (many colours).
//  2. Real keys and clicks reach the game: holding the right arrow rolls the player further than the
//     native run without keys, and a click in the sky spawns a tire.
//  3. The canvas follows the window's size.
//  4. Every replay given passes in the page (?replay=...).
//  5. A best time and its ghost outlast a reload: level 01 won in the page is stored in IndexedDB
//     (game/web/persist.pre.js), and the next page load shows that best time and loads the ghost.
'use strict';
const fs = require('fs');
const path = require('path');

function parseArgs(argv) {
  const opts = { replays: [] };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (a.startsWith('--')) opts[a.slice(2)] = argv[++i];
    else opts.replays.push(a);
  }
  return opts;
}

const opts = parseArgs(process.argv.slice(2));
const puppeteer = require(path.join(opts.modules, 'puppeteer-core'));
let failures = 0;
let passes = 0;
function report(ok, what) {
  console.log(`${ok ? 'PASS' : 'FAIL'}: ${what}`);
  if (ok) ++passes;
  else ++failures;
}

// How many representable doubles lie between a and b (0: the same bits).
function ulps(a, b) {
  const view = new DataView(new ArrayBuffer(8));
  const key = (x) => {
    view.setFloat64(0, x);
    const bits = view.getBigInt64(0);
    return bits < 0n ? -(bits & 0x7fffffffffffffffn) : bits;
  };
  const d = key(a) - key(b);
  return d < 0n ? -d : d;
}

async function openPage(browser, query, log) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 720 });
  page.on('console', (m) => log.push(`[${m.type()}] ${m.text()}`));
  page.on('pageerror', (e) => log.push(`[pageerror] ${e.message}`));
  await page.goto(opts.url + query, { waitUntil: 'load' });
  return page;
}

async function waitSummary(page, timeout) {
  await page.waitForFunction(() => document.getElementById('summary').dataset.exit !== undefined, {
    timeout,
    polling: 100,
  });
  return page.$eval('#summary', (e) => ({ text: e.textContent, exit: Number(e.dataset.exit) }));
}

// Distinct colours of a screenshot, and the share of its most common one, counted in the page.
async function colours(page, png) {
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, c.width, c.height).data;
    const counts = new Map();
    for (let i = 0; i < px.length; i += 4) {
      const k = (px[i] << 16) | (px[i + 1] << 8) | px[i + 2];
      counts.set(k, (counts.get(k) || 0) + 1);
    }
    const top = Math.max(...counts.values());
    return { distinct: counts.size, top_share: top / (px.length / 4) };
  }, png);
}

function dumpLog(name, log) {
  fs.writeFileSync(path.join(opts.out, name + '.log'), log.join('\n') + '\n');
}

async function main() {
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-gl=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1280,720'],
  });
  try {
    // 1. Scripted frames against the native run, and the picture.
    {
      const log = [];
      const page = await openPage(browser, '?level=levels/01-first-roll.json&frames=300&press=right:0-299', log);
      const s = await waitSummary(page, 180000);
      dumpLog('frames-300', log);
      const web = JSON.parse(s.text);
      const native = JSON.parse(fs.readFileSync(opts.native, 'utf8'));
      fs.writeFileSync(path.join(opts.out, 'web-300.json'), s.text + '\n');
      console.log(`native player: ${JSON.stringify(native.player)}`);
      console.log(`web    player: ${JSON.stringify(web.player)}`);
      console.log(
        `frame_ms (median, whole frame): native ${native.frame_ms.frame.median}, web ${web.frame_ms.frame.median}`,
      );
      const same =
        s.exit === 0 &&
        Array.isArray(web.player) &&
        web.player.length === 2 &&
        web.player[0] === native.player[0] &&
        web.player[1] === native.player[1] &&
        web.ticks === native.ticks;
      const diff = Array.isArray(web.player)
        ? web.player.map((x, i) => `${ulps(x, native.player[i])} ulp`).join(', ')
        : 'no player';
      report(same, `?frames=300&press=right:0-299 ends where the native game does, bit for bit (${diff})`);
      const shot = await page.screenshot({ encoding: 'base64' });
      fs.writeFileSync(path.join(opts.out, 'frames-300.png'), Buffer.from(shot, 'base64'));
      const c = await colours(page, shot);
      report(
        c.distinct >= 16 && c.top_share < 0.95,
        `the page draws a picture (${c.distinct} colours, the commonest on ${(100 * c.top_share).toFixed(1)} %)`,
      );
      await page.close();
    }

    // 2. Real input, and 3. the canvas following the window.
    {
      const log = [];
      const page = await openPage(browser, '?level=levels/01-first-roll.json&frames=400', log);
      await page.waitForFunction(() => document.getElementById('status').textContent === '', { timeout: 60000 });
      await page.waitForFunction(() => document.getElementById('canvas').width === 1280, { timeout: 20000 });
      await page.keyboard.down('ArrowRight');
      await page.mouse.click(640, 60);
      await page.setViewport({ width: 960, height: 540 });
      let followed = true;
      try {
        await page.waitForFunction(
          () => {
            const c = document.getElementById('canvas');
            return c.width === 960 && c.height === 540;
          },
          { timeout: 20000 },
        );
      } catch (e) {
        followed = false;
      }
      const size = await page.$eval('#canvas', (c) => `${c.width}x${c.height}`);
      report(followed, `the canvas follows the window from 1280x720 to 960x540 (${size})`);
      const s = await waitSummary(page, 120000);
      await page.keyboard.up('ArrowRight');
      dumpLog('input-400', log);
      const web = JSON.parse(s.text);
      const idle = JSON.parse(fs.readFileSync(opts.nativeIdle || opts['native-idle'], 'utf8'));
      report(
        web.player[0] > idle.player[0] + 1.0,
        `a held right arrow rolls the player (x ${web.player[0].toFixed(2)} m, ${idle.player[0].toFixed(2)} m without keys)`,
      );
      report(web.tires >= 2, `a click in the sky spawns a tire (${web.tires} tires)`);
      const shot = await page.screenshot({ encoding: 'base64' });
      fs.writeFileSync(path.join(opts.out, 'input-400.png'), Buffer.from(shot, 'base64'));
      await page.close();
    }

    // 5. The progress in IndexedDB, across a reload.
    {
      const log = [];
      const page = await openPage(browser, '?level=levels/01-first-roll.json&frames=450&press=right:0-449', log);
      const s = await waitSummary(page, 300000);
      const won = JSON.parse(s.text);
      let stored = true;
      try {
        await page.waitForFunction(() => Number(document.getElementById('summary').dataset.persisted) >= 1, {
          timeout: 30000,
          polling: 100,
        });
      } catch (e) {
        stored = false;
      }
      dumpLog('progress-win', log);
      await page.close();
      const best = won.progress && won.progress.run && won.progress.run.won ? won.progress.best_time : undefined;
      report(best !== undefined && stored, `a win in the page is stored in IndexedDB (best ${best} s, stored: ${stored})`);
      const again = [];
      const next = await openPage(browser, '?level=levels/01-first-roll.json&frames=5', again);
      const n = await waitSummary(next, 120000);
      dumpLog('progress-reload', again);
      const later = JSON.parse(n.text);
      const p = later.progress || {};
      report(
        best !== undefined && p.best_time === best && p.ghost && p.ghost.loaded === true,
        `after a reload the page shows that best time and its ghost (best ${p.best_time} s, ghost loaded: ${
          p.ghost && p.ghost.loaded
        })`,
      );
      await next.close();
    }

    // 4. The replays.
    const results = [];
    for (const replay of opts.replays) {
      const log = [];
      const page = await openPage(browser, '?replay=' + replay, log);
      let s;
      try {
        s = await waitSummary(page, 600000);
      } catch (e) {
        s = { text: `{"error": "no result: ${e.message}"}`, exit: -1 };
      }
      const name = path.basename(replay, '.json');
      dumpLog('replay-' + name, log);
      let r;
      try {
        r = JSON.parse(s.text);
      } catch (e) {
        r = { error: s.text };
      }
      results.push(r);
      const detail = r.pass
        ? `${r.ticks} ticks, ${r.status}, ${Math.round(r.ms)} ms`
        : JSON.stringify(r.failures || r.errors || r.error).slice(0, 400);
      report(r.pass === true && s.exit === 0, `replay ${name} passes in the page (${detail})`);
      await page.close();
    }
    fs.writeFileSync(path.join(opts.out, 'replays.json'), JSON.stringify(results, null, 1) + '\n');
  } finally {
    await browser.close();
  }
  console.log(`${passes} passed, ${failures} failed`);
  process.exit(failures ? 1 : 0);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
