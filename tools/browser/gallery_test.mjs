// The gallery in a real browser: opens GALLERY/index.html from file:// (no web server) in
// headless Chromium — the system's /usr/bin/chromium (or $CHROMIUM) driven by the pinned
// playwright-core, WebGL by SwiftShader — and checks that
//   - every glb of the gallery has a viewer, its models/NAME.js carries the same bytes,
//     and every viewer loads its model and draws it (not blank), with no console error;
//   - the beating heart's morph-target weights at several times equal those splinekit
//     wrote in beating_heart.glb (read back here from the file, not through three.js);
//   - two screenshots of the playing heart at different times differ and are not blank;
//   - dragging turns a view, the wheel zooms it, the pause button and the time slider work.
// It prints the page's size and load times. With --screenshot, it saves the window with the
// heart's row at the top, playing. Usage:
//   node gallery_test.mjs GALLERY [--out DIR] [--screenshot FILE.png]
// DIR (default GALLERY/../browser-test) receives the heart's two screenshots, a screenshot of
// every view (views/NAME.png) and the measurements (measurements.json).
import { chromium } from 'playwright-core';
import { existsSync, mkdirSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { inflateSync } from 'node:zlib';

const args = process.argv.slice(2);
const option = (name) => {
    const i = args.indexOf(name);
    return i >= 0 ? args.splice(i, 2)[1] : undefined;
};
const outDir = option('--out');
const screenshotPath = option('--screenshot');
if (args.length !== 1) {
    console.error('usage: node gallery_test.mjs GALLERY [--out DIR] [--screenshot FILE.png]');
    process.exit(2);
}
const gallery = resolve(args[0]);
const out = resolve(outDir ?? join(dirname(gallery), 'browser-test'));
mkdirSync(join(out, 'views'), { recursive: true });
const executablePath = process.env.CHROMIUM ?? '/usr/bin/chromium';

const failures = [];
function check(ok, what) {
    if (!ok) {
        failures.push(what);
        console.error(`FAIL ${what}`);
    }
    return ok;
}

// ---- glb, read here without three.js ----------------------------------------------------

const COMPONENTS = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };

/** The glb's JSON and binary chunk. */
function readGlb(path) {
    const b = readFileSync(path);
    if (b.toString('latin1', 0, 4) !== 'glTF' || b.readUInt32LE(4) !== 2) {
        throw new Error(`${path} is not a glTF 2 binary`);
    }
    let json = null;
    let bin = null;
    for (let at = 12; at < b.readUInt32LE(8); ) {
        const length = b.readUInt32LE(at);
        const type = b.toString('latin1', at + 4, at + 8);
        const chunk = b.subarray(at + 8, at + 8 + length);
        if (type === 'JSON') json = JSON.parse(chunk.toString('utf8'));
        if (type === 'BIN\0') bin = chunk;
        at += 8 + length;
    }
    return { json, bin };
}

/** A float accessor's values, as arrays of its components. */
function floats({ json, bin }, index) {
    const a = json.accessors[index];
    if (a.componentType !== 5126) throw new Error(`accessor ${index} is not float`);
    const view = json.bufferViews[a.bufferView];
    const n = COMPONENTS[a.type];
    const stride = view.byteStride ?? 4 * n;
    const base = (view.byteOffset ?? 0) + (a.byteOffset ?? 0);
    const values = [];
    for (let i = 0; i < a.count; i++) {
        const row = [];
        for (let c = 0; c < n; c++) row.push(bin.readFloatLE(base + i * stride + 4 * c));
        values.push(row);
    }
    return values;
}

/** The weights each animated node has at time t by its LINEAR sampler, by node index. */
function weightsAt(glb, t) {
    const out = new Map();
    for (const animation of glb.json.animations ?? []) {
        for (const channel of animation.channels) {
            if (channel.target.path !== 'weights') continue;
            const sampler = animation.samplers[channel.sampler];
            if ((sampler.interpolation ?? 'LINEAR') !== 'LINEAR') throw new Error('only LINEAR samplers are read');
            const times = floats(glb, sampler.input).map((r) => r[0]);
            const values = floats(glb, sampler.output).map((r) => r[0]);
            const targets = values.length / times.length;
            const frame = (k) => values.slice(k * targets, (k + 1) * targets);
            let w;
            if (t <= times[0]) {
                w = frame(0);
            } else if (t >= times[times.length - 1]) {
                w = frame(times.length - 1);
            } else {
                let k = 0;
                while (times[k + 1] < t) k++;
                const s = (t - times[k]) / (times[k + 1] - times[k]);
                const [a, b] = [frame(k), frame(k + 1)];
                w = a.map((x, i) => x + s * (b[i] - x));
            }
            out.set(channel.target.node, w);
        }
    }
    return out;
}

// ---- PNG, decoded here (8-bit RGB or RGBA, as Chromium writes them) ----------------------

function decodePng(buffer) {
    let at = 8;
    let width = 0;
    let height = 0;
    let channels = 0;
    const idat = [];
    while (at < buffer.length) {
        const length = buffer.readUInt32BE(at);
        const type = buffer.toString('latin1', at + 4, at + 8);
        const data = buffer.subarray(at + 8, at + 8 + length);
        if (type === 'IHDR') {
            width = data.readUInt32BE(0);
            height = data.readUInt32BE(4);
            if (data[8] !== 8 || data[12] !== 0 || (data[9] !== 2 && data[9] !== 6)) {
                throw new Error('only 8-bit non-interlaced RGB(A) PNGs are read');
            }
            channels = data[9] === 6 ? 4 : 3;
        } else if (type === 'IDAT') {
            idat.push(data);
        }
        at += 12 + length;
    }
    const raw = inflateSync(Buffer.concat(idat));
    const row = width * channels;
    const pixels = Buffer.alloc(height * row);
    for (let y = 0; y < height; y++) {
        const filter = raw[y * (row + 1)];
        const line = raw.subarray(y * (row + 1) + 1, (y + 1) * (row + 1));
        for (let x = 0; x < row; x++) {
            const a = x >= channels ? pixels[y * row + x - channels] : 0;
            const b = y > 0 ? pixels[(y - 1) * row + x] : 0;
            const c = x >= channels && y > 0 ? pixels[(y - 1) * row + x - channels] : 0;
            let v = line[x];
            if (filter === 1) v += a;
            else if (filter === 2) v += b;
            else if (filter === 3) v += (a + b) >> 1;
            else if (filter === 4) {
                const p = a + b - c;
                const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - c)];
                v += pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            }
            pixels[y * row + x] = v & 255;
        }
    }
    const rgb = (i) => [pixels[i * channels], pixels[i * channels + 1], pixels[i * channels + 2]];
    return { width, height, rgb };
}

const far = (p, q) => Math.max(Math.abs(p[0] - q[0]), Math.abs(p[1] - q[1]), Math.abs(p[2] - q[2])) > 24;

/** Pixels far from the background colour. */
function inked(png, background) {
    let n = 0;
    for (let i = 0; i < png.width * png.height; i++) if (far(png.rgb(i), background)) n++;
    return n;
}

/** Pixels that differ between two pictures of one size. */
function differing(p, q) {
    let n = 0;
    for (let i = 0; i < p.width * p.height; i++) if (far(p.rgb(i), q.rgb(i))) n++;
    return n;
}

// ---- the page ----------------------------------------------------------------------------

const index = join(gallery, 'index.html');
if (!existsSync(index)) {
    console.error(`${index} is missing: run splinekit gallery first`);
    process.exit(2);
}
const glbs = readdirSync(gallery).filter((f) => f.endsWith('.glb')).map((f) => f.slice(0, -4)).sort();
check(glbs.length > 0, `the gallery in ${gallery} has glb files`);
for (const stem of glbs) {
    const script = readFileSync(join(gallery, 'models', `${stem}.js`), 'utf8');
    const m = /^splinekitGallery\.addModel\("([^"]+)", "([A-Za-z0-9+/=]*)"\);\n$/.exec(script);
    check(m && m[1] === stem, `models/${stem}.js hands over the model '${stem}'`);
    check(m && Buffer.from(m[2], 'base64').equals(readFileSync(join(gallery, `${stem}.glb`))), `models/${stem}.js carries ${stem}.glb byte for byte`);
}

const browser = await chromium.launch({
    executablePath,
    headless: true,
    // SwiftShader's WebGL (no GPU); /tmp instead of a container's small /dev/shm.
    args: ['--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist', '--disable-dev-shm-usage'],
});
const messages = [];
/** A page of the gallery, its console recorded. */
async function open(options) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1, ...options });
    const page = await context.newPage();
    page.on('console', (m) => messages.push({ type: m.type(), text: m.text() }));
    page.on('pageerror', (e) => messages.push({ type: 'pageerror', text: String(e) }));
    page.on('requestfailed', (r) => messages.push({ type: 'requestfailed', text: `${r.url()}: ${r.failure()?.errorText}` }));
    await page.goto(pathToFileURL(index).href, { waitUntil: 'load' });
    return page;
}
const view = (name) => `figure[data-view*='"name":"${name}"']`;
/** Files the page has read: the page, its scripts (models included) and the pictures shown. */
const filesRead = (page) =>
    page.evaluate(() =>
        [location.href]
            .concat([...document.scripts].filter((s) => s.src).map((s) => s.src))
            .concat([...document.images].filter((i) => i.complete && i.naturalWidth > 0).map((i) => i.currentSrc)),
    );
const sizeOf = (f) => statSync(f).size;
const bytesOf = (urls) => [...new Set(urls)].map((u) => decodeURIComponent(new URL(u).pathname)).reduce((s, f) => s + sizeOf(f), 0);
const heart = (body) => `(() => { const v = window.splinekitGallery.views.find((v) => v.name === 'beating_heart'); ${body} })()`;
const measured = {};

try {
    // 1. As a reader opens it: the first screen's views load by themselves; the heart,
    //    scrolled to, plays by itself.
    const started = Date.now();
    const page = await open({});
    measured.loadMs = await page.evaluate(() => performance.getEntriesByType('navigation')[0].loadEventEnd);
    await page.waitForFunction(
        () =>
            window.splinekitGallery.views.some((v) => v.visible) &&
            window.splinekitGallery.views.filter((v) => v.visible).every((v) => v.state === 'ready' || v.state === 'error'),
        null,
        { timeout: 60000 },
    );
    measured.firstScreenMs = Date.now() - started;
    measured.firstScreenViews = await page.evaluate(() => window.splinekitGallery.views.filter((v) => v.visible).map((v) => v.name));
    measured.firstScreenBytes = bytesOf(await filesRead(page));
    check(await page.evaluate(() => window.splinekitGallery.revision) !== null, 'three.js loaded');

    await page.locator(view('beating_heart')).scrollIntoViewIfNeeded();
    await page.waitForFunction(heart(`return v.state === 'ready' || v.state === 'error';`), null, { timeout: 60000 });
    check(await page.evaluate(heart('return v.state;')) === 'ready', 'the heart loads when scrolled to');
    check(await page.evaluate(heart('return v.playing;')), 'the heart plays by itself');

    // The heart's morph weights in three.js against the glb's.
    const heartGlb = readGlb(join(gallery, 'beating_heart.glb'));
    check((heartGlb.json.animations ?? []).length > 0, `beating_heart.glb has animations (${(heartGlb.json.animations ?? []).length})`);
    const period = await page.evaluate(heart('v.pause(); return v.period;'));
    const times = [0, 0.05, 0.123, 0.31, 0.5, 0.6875, 0.9, 0.95, 0.99];
    let compared = 0;
    let worst = 0;
    for (const t of times) {
        const got = await page.evaluate(heart(`v.setTime(${t}); return v.influences();`));
        const want = weightsAt(heartGlb, t);
        check(got.length === want.size, `heart at ${t} s: every animated node has weights in three.js (${got.length} of ${want.size})`);
        for (const { node, weights } of got) {
            const w = want.get(node);
            if (!check(w && w.length === weights.length, `heart at ${t} s, node ${node}: as many weights as the glb's targets`)) continue;
            for (let i = 0; i < w.length; i++) {
                worst = Math.max(worst, Math.abs(w[i] - weights[i]));
                compared++;
            }
        }
    }
    check(compared > 0 && worst <= 1e-6, `heart: ${compared} morph weights at ${times.length} times equal the glb's (largest difference ${worst.toExponential(2)})`);

    // Two screenshots of the playing heart, a quarter of a period or more apart.
    const heartCanvas = page.locator(`${view('beating_heart')} canvas`);
    await page.evaluate(heart('v.play();'));
    const shots = [];
    for (const k of ['a', 'b']) {
        if (shots.length > 0) {
            const t0 = shots[0].time;
            await page.waitForFunction(
                heart(`const d = Math.abs(v.time - ${t0}); return Math.min(d, ${period} - d) > ${period / 4};`),
                null,
                { timeout: 30000 },
            );
        }
        const time = await page.evaluate(heart('return v.time;'));
        const png = await heartCanvas.screenshot({ path: join(out, `heart-${k}.png`) });
        shots.push({ png: decodePng(png), time });
    }
    check(await page.evaluate(heart('return v.playing;')), 'the heart played through the screenshots');
    for (const s of shots) {
        const ink = inked(s.png, [255, 255, 255]);
        check(ink > 0.005 * s.png.width * s.png.height, `heart screenshot near ${s.time.toFixed(2)} s is not blank (${ink} pixels drawn)`);
    }
    const diff = differing(shots[0].png, shots[1].png);
    check(diff > 200, `the heart's screenshots near ${shots[0].time.toFixed(2)} s and ${shots[1].time.toFixed(2)} s differ (${diff} pixels)`);

    // The pause button and the slider.
    const bar = page.locator(`${view('beating_heart')} .timebar`);
    await bar.locator('button').click();
    check((await page.evaluate(heart('return v.playing;'))) === false, 'the pause button pauses the heart');
    await bar.locator('input').fill('0.4');
    const scrubbed = await page.evaluate(heart('return v.time;'));
    check(Math.abs(scrubbed - 0.4) < 1e-9, `the slider scrubs the heart to 0.4 s (${scrubbed})`);
    await bar.locator('button').click();
    check(await page.evaluate(heart('return v.playing;')), 'the play button plays the heart again');

    if (screenshotPath) {
        // The page with the heart's row at the top: the heart playing, surfaces beside it.
        await page.evaluate(heart('window.scrollTo(0, v.figure.getBoundingClientRect().top + window.scrollY - 16);'));
        await page.waitForFunction(
            () => window.splinekitGallery.views.filter((v) => v.visible).every((v) => v.state === 'ready' || v.state === 'error'),
            null,
            { timeout: 60000 },
        );
        await page.waitForTimeout(300);
        await page.screenshot({ path: resolve(screenshotPath) });
    }
    await page.context().close();

    // 2. Every view, scrolled to in turn, loads its model and draws it; with reduced motion,
    //    so that the animations (which then stay paused) leave the CPU to the loading.
    const all = await open({ reducedMotion: 'reduce' });
    const names = await all.evaluate(() => window.splinekitGallery.views.map((v) => v.name));
    check(JSON.stringify([...names].sort()) === JSON.stringify(glbs), `a viewer for every glb (viewers: ${names.length}, glb files: ${glbs.length})`);
    const viewStates = {};
    const everyStarted = Date.now();
    for (const name of names) {
        const viewStarted = Date.now();
        const state = await all.evaluate(async (name) => {
            const v = window.splinekitGallery.views.find((v) => v.name === name);
            v.figure.scrollIntoView({ block: 'center' });
            while (v.state === 'poster') await new Promise((r) => setTimeout(r, 10));
            await v.whenReady;
            await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
            return { state: v.state, error: v.error, playing: v.playing, animated: !!v.mixer };
        }, name);
        viewStates[name] = state;
        if (!check(state.state === 'ready', `${name}: the viewer loaded its model (${state.state}${state.error ? `: ${state.error}` : ''})`)) continue;
        check(!(state.animated && state.playing), `${name}: stays paused when the reader prefers reduced motion`);
        const shot = decodePng(await all.locator(`${view(name)} canvas`).screenshot({ path: join(out, 'views', `${name}.png`) }));
        const background = await all.evaluate((name) => window.splinekitGallery.views.find((v) => v.name === name).spec.background, name);
        const ink = inked(shot, background.map((c) => Math.round(c * 255)));
        if (process.env.VERBOSE) console.log(`  ${name}: ${Date.now() - viewStarted} ms`);
        check(ink > 0.002 * shot.width * shot.height, `${name}: the view draws the model (${ink} of ${shot.width}×${shot.height} pixels off the background)`);
    }
    measured.everyMs = Date.now() - everyStarted;

    // The triangle family (issue 36) in the page: a Bézier triangle with its net, a GERBS
    // triangle with its three locals (their edges as line strips), the blending surface over
    // a triangulated sphere with one local moved, and one animated (the viewer plays it).
    const lineStrips = (stem) =>
        (readGlb(join(gallery, `${stem}.glb`)).json.meshes ?? []).flatMap((m) => m.primitives).filter((p) => p.mode === 3).length;
    for (const [name, strips] of [['bezier_triangle_net', 9], ['gerbs_triangle_locals', 9], ['blending_sphere_moved', 0], ['blending_sphere_animated', 0]]) {
        if (!check(glbs.includes(name), `the gallery shows ${name}`)) continue;
        check(viewStates[name]?.state === 'ready', `${name}: drawn in the browser`);
        check(lineStrips(name) >= strips, `${name}: at least ${strips} line strips (${lineStrips(name)})`);
    }
    const animatedSphere = readGlb(join(gallery, 'blending_sphere_animated.glb'));
    check((animatedSphere.json.animations ?? []).length > 0 && viewStates.blending_sphere_animated?.animated, 'blending_sphere_animated carries an animation the viewer plays');
    measured.everyBytes = bytesOf(await filesRead(all));

    // Orbit and zoom on a surface.
    const torus = all.locator(`${view('nurbs_torus')} canvas`);
    await torus.scrollIntoViewIfNeeded();
    const box = await torus.boundingBox();
    const torusView = (body) => `(() => { const v = window.splinekitGallery.views.find((v) => v.name === 'nurbs_torus'); ${body} })()`;
    const distance = torusView('return v.camera.position.distanceTo(v.controls.target);');
    const still = decodePng(await torus.screenshot());
    const c0 = await all.evaluate(torusView('return v.camera.position.toArray();'));
    await all.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await all.mouse.down();
    await all.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 + 40, { steps: 8 });
    await all.mouse.up();
    const c1 = await all.evaluate(torusView('return v.camera.position.toArray();'));
    const turned = decodePng(await torus.screenshot());
    check(Math.hypot(...c0.map((x, i) => x - c1[i])) > 1e-3, 'dragging turns the torus view (its camera moves)');
    check(differing(still, turned) > 200, 'dragging turns the torus view (its picture changes)');
    const d1 = await all.evaluate(distance);
    await all.mouse.wheel(0, -300);
    await all.waitForTimeout(100);
    const d2 = await all.evaluate(distance);
    check(d2 < d1 * 0.95, `the wheel zooms in on the torus (distance ${d1.toFixed(2)} → ${d2.toFixed(2)})`);
    await all.locator(`${view('nurbs_torus')} canvas`).dblclick();
    const c2 = await all.evaluate(torusView('return v.camera.position.toArray();'));
    check(Math.hypot(...c0.map((x, i) => x - c2[i])) < 1e-6, 'a double-click brings the torus view back');
} finally {
    await browser.close();
}

// Nothing went wrong on the way.
const bad = messages.filter((m) => ['error', 'warning', 'pageerror', 'requestfailed'].includes(m.type));
for (const m of bad) console.error(`  console ${m.type}: ${m.text}`);
check(bad.length === 0, `no console errors or warnings (${bad.length})`);

// Size and time.
const scripts = ['vendor/three-gltf-orbit.min.js', 'viewer.js'].map((f) => sizeOf(join(gallery, f)));
const models = readdirSync(join(gallery, 'models')).reduce((s, f) => s + sizeOf(join(gallery, 'models', f)), 0);
const kib = (n) => `${(n / 1024).toFixed(0)} KiB`;
console.log(
    `page: index.html ${kib(sizeOf(index))}, three.js bundle ${kib(scripts[0])}, viewer.js ${kib(scripts[1])}, ` +
        `models/ ${kib(models)} for ${glbs.length} models; the first screen (${measured.firstScreenViews.length} views) reads ` +
        `${kib(measured.firstScreenBytes)}, every view ${kib(measured.everyBytes)}`,
);
console.log(
    `time: load event ${measured.loadMs.toFixed(0)} ms, the first screen's views drawn ${measured.firstScreenMs} ms after ` +
        `opening, every view scrolled to and drawn in ${(measured.everyMs / 1000).toFixed(1)} s (SwiftShader, no GPU)`,
);
writeFileSync(join(out, 'measurements.json'), `${JSON.stringify({ ...measured, models, scripts }, null, 1)}\n`);

if (failures.length > 0) {
    console.error(`gallery in the browser: ${failures.length} check(s) failed`);
    process.exit(1);
}
console.log(`gallery in the browser: every check passed (${gallery})`);
