// The Python tour notebook (docs/tour.ipynb), executed and exported to HTML by nbconvert,
// in headless Chromium (the gallery test's: /usr/bin/chromium or $CHROMIUM, driven by the
// pinned playwright-core, WebGL by SwiftShader), opened from file://. Checks that
//   - every splinekit view of the page (div.splinekit-view) loads its model (state 'ready');
//   - every view draws something: enough pixels differ from its background;
//   - an animated view plays (its time advances and its picture changes) and pauses;
//   - the page logs no console error or warning and no page error.
// Usage: node notebook_test.mjs PAGE.html [--out DIR]; DIR (default beside PAGE) receives
// a screenshot of the page (tour.png) and one of every view (view-K.png).
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
const at = args.indexOf('--out');
const outDir = at >= 0 ? args.splice(at, 2)[1] : undefined;
if (args.length !== 1) {
    console.error('usage: node notebook_test.mjs PAGE.html [--out DIR]');
    process.exit(2);
}
const pagePath = resolve(args[0]);
const out = resolve(outDir ?? join(dirname(pagePath), 'notebook-browser'));
mkdirSync(out, { recursive: true });

const failures = [];
function check(ok, what) {
    if (!ok) {
        failures.push(what);
        console.error(`FAIL ${what}`);
    }
    return ok;
}

const started = Date.now();
const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: ['--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist', '--disable-dev-shm-usage'],
});
const context = await browser.newContext({ viewport: { width: 1100, height: 900 }, deviceScaleFactor: 1 });
const page = await context.newPage();
const messages = [];
page.on('console', (m) => messages.push({ type: m.type(), text: m.text() }));
page.on('pageerror', (e) => messages.push({ type: 'pageerror', text: String(e) }));
page.on('requestfailed', (r) => messages.push({ type: 'requestfailed', text: `${r.url()}: ${r.failure()?.errorText}` }));
await page.goto(pathToFileURL(pagePath).href, { waitUntil: 'load' });

const expected = await page.locator('div.splinekit-view').count();
check(expected >= 5, `the page has the tour's views (found ${expected})`);
// Every view settles: ready or failed.
await page.waitForFunction(
    (n) => window.splinekitNotebook && window.splinekitNotebook.views.length === n && window.splinekitNotebook.views.every((v) => v.state !== 'loading'),
    expected,
    { timeout: 60_000 },
).catch(() => check(false, 'every view settled within 60 s'));
const states = await page.evaluate(() => (window.splinekitNotebook?.views ?? []).map((v) => ({ state: v.state, error: v.error, id: v.box.id, animated: !!v.mixer })));
states.forEach((s, k) => check(s.state === 'ready', `view ${k} (${s.id}) is ready${s.error ? `: ${s.error}` : ''}`));

// Each view draws its model: at least 0.3 % of its pixels differ from the background.
for (let k = 0; k < states.length; k++) {
    const { drawn, total } = await page.evaluate((k) => {
        const v = window.splinekitNotebook.views[k];
        return { drawn: v.drawn(), total: v.canvas ? v.canvas.width * v.canvas.height : 0 };
    }, k);
    check(total > 0 && drawn > 0.003 * total, `view ${k} draws something (${drawn} of ${total} pixels)`);
    const box = page.locator(`#${states[k].id}`);
    await box.scrollIntoViewIfNeeded();
    await box.screenshot({ path: join(out, `view-${k}.png`) });
}

// Only animated views show the play/pause bar.
const bars = await page.evaluate(() =>
    window.splinekitNotebook.views.map((v) => getComputedStyle(v.box.querySelector('.splinekit-timebar')).display !== 'none'),
);
states.forEach((s, k) => check(bars[k] === s.animated, `view ${k} shows its time bar only if animated`));

// An animated view plays: its clock advances and its picture changes; pause stops it.
const animated = states.findIndex((s) => s.animated);
if (check(animated >= 0, 'the tour has an animated view')) {
    const picture = (k) =>
        page.evaluate((k) => {
            const v = window.splinekitNotebook.views[k];
            v.draw();
            return v.canvas.toDataURL();
        }, k);
    const t0 = await page.evaluate((k) => window.splinekitNotebook.views[k].time, animated);
    const a = await picture(animated);
    await page.waitForTimeout(400);
    const t1 = await page.evaluate((k) => window.splinekitNotebook.views[k].time, animated);
    const b = await picture(animated);
    check(t1 !== t0, `the animation's clock advances (${t0.toFixed(3)} → ${t1.toFixed(3)} s)`);
    check(a !== b, 'the animated picture changes while playing');
    await page.locator(`#${states[animated].id} .splinekit-timebar button`).click();
    const paused = await page.evaluate((k) => window.splinekitNotebook.views[k].playing, animated);
    check(paused === false, 'the button pauses the animation');
}

await page.screenshot({ path: join(out, 'tour.png'), fullPage: true });
const bad = messages.filter((m) => m.type === 'error' || m.type === 'warning' || m.type === 'pageerror' || m.type === 'requestfailed');
for (const m of bad) console.error(`  console ${m.type}: ${m.text}`);
check(bad.length === 0, `no console errors or warnings (${bad.length})`);
await browser.close();

console.log(`notebook in the browser: ${states.length} views, ${((Date.now() - started) / 1000).toFixed(1)} s; screenshots in ${out}`);
if (failures.length > 0) {
    console.error(`notebook in the browser: ${failures.length} check(s) failed`);
    process.exit(1);
}
console.log(`notebook in the browser: every check passed (${pagePath})`);
