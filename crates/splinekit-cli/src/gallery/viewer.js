/* splinekit gallery viewer: turns each figure's glTF export in the page.
 *
 * Written by `splinekit gallery` next to index.html; needs vendor/three-gltf-orbit.min.js
 * (three.js, loaded before this file), which defines the global SplinekitThree. The page
 * must work when opened from the file system, where Chromium refuses fetch, XHR and ES
 * module imports of local files: so this is a classic script, and every model comes as
 * models/NAME.js, a classic script that hands the glb's bytes (base64) to
 * splinekitGallery.addModel. A figure's model is loaded when the figure comes near the
 * window; until then (and if it fails) its rendered picture shows as the poster.
 *
 * WebGL draws its lines one pixel wide, so every line of a model is drawn by a LineSegments2
 * (three's screen-space wide lines) LINE_WIDTH CSS pixels wide, its points following the
 * line's morph targets; the line itself stays, hidden, for the animation to drive.
 *
 * One WebGL renderer draws every view and copies the picture into the view's own 2-D
 * canvas, so the page never holds more than one WebGL context (browsers drop the oldest
 * beyond about 16). A view is redrawn only when it moves, plays, or is resized.
 *
 * Animations play as soon as they are loaded, unless the reader prefers reduced motion.
 *
 * window.splinekitGallery.views lists the views for tests: state ('poster', 'loading',
 * 'ready' or 'error'), setTime(t), play(), pause(), influences() (morph-target weights
 * by glTF node) and whenReady.
 */
(function () {
    'use strict';
    const T = window.SplinekitThree;
    const gallery = { views: [], addModel, revision: T ? T.REVISION : null };
    // Width of the models' lines in CSS pixels (the pictures' are 1.5 to 5).
    const LINE_WIDTH = 2.5;
    window.splinekitGallery = gallery;

    // models/NAME.js scripts that are loading: name -> { resolve, reject }.
    const waiting = new Map();

    /** Called by models/NAME.js with the glb's bytes in base64. */
    function addModel(name, base64) {
        const w = waiting.get(name);
        if (w) {
            waiting.delete(name);
            w.resolve(base64);
        }
    }

    /** Loads models/NAME.js by a script tag (allowed from file://); resolves with its base64. */
    function loadModelScript(name, src) {
        return new Promise((resolve, reject) => {
            waiting.set(name, { resolve, reject });
            const script = document.createElement('script');
            script.src = src;
            script.async = true;
            script.onerror = () => {
                waiting.delete(name);
                reject(new Error(`${src} could not be loaded`));
            };
            script.onload = () => {
                if (waiting.has(name)) {
                    waiting.delete(name);
                    reject(new Error(`${src} did not define the model '${name}'`));
                }
            };
            document.head.appendChild(script);
        });
    }

    function base64ToArrayBuffer(base64) {
        const text = atob(base64);
        const bytes = new Uint8Array(text.length);
        for (let i = 0; i < text.length; i++) {
            bytes[i] = text.charCodeAt(i);
        }
        return bytes.buffer;
    }

    let sharedRenderer = null;
    function renderer() {
        if (!sharedRenderer) {
            sharedRenderer = new T.WebGLRenderer({ antialias: true });
            sharedRenderer.setPixelRatio(1);
        }
        return sharedRenderer;
    }

    /** Drawing: one animation-frame loop, running only while some view needs drawing. */
    let frameRequested = false;
    let lastFrame = null;
    function requestFrame() {
        if (!frameRequested) {
            frameRequested = true;
            requestAnimationFrame(frame);
        }
    }
    function frame(now) {
        frameRequested = false;
        const dt = lastFrame === null ? 0 : Math.min((now - lastFrame) / 1000, 0.1);
        let again = false;
        for (const view of gallery.views) {
            if (view.state !== 'ready' || !view.visible) {
                continue;
            }
            if (view.playing) {
                view.advance(dt);
                again = true;
            }
            if (view.dirty) {
                view.draw();
            }
        }
        lastFrame = again ? now : null;
        if (again) {
            requestFrame();
        }
    }

    function formatTime(t) {
        return `${t.toFixed(2)} s`;
    }

    class View {
        constructor(figure) {
            this.figure = figure;
            this.spec = JSON.parse(figure.dataset.view);
            this.name = this.spec.name;
            this.box = figure.querySelector('.view');
            this.poster = this.box.querySelector('img');
            this.state = 'poster';
            this.error = null;
            this.visible = false;
            this.dirty = false;
            this.playing = false;
            this.time = 0;
            this.period = 0;
            this.whenReady = null;
        }

        /** Loads and sets up the model once; resolves when it is ready or has failed. */
        load() {
            if (this.whenReady) {
                return this.whenReady;
            }
            this.state = 'loading';
            this.box.classList.add('loading');
            this.whenReady = (async () => {
                try {
                    const base64 = await loadModelScript(this.name, this.spec.src);
                    const gltf = await new T.GLTFLoader().parseAsync(base64ToArrayBuffer(base64), '');
                    this.setUp(gltf);
                    this.state = 'ready';
                    this.box.classList.remove('loading');
                    this.box.classList.add('ready');
                    this.dirty = true;
                    requestFrame();
                } catch (e) {
                    this.state = 'error';
                    this.error = String(e && e.message ? e.message : e);
                    this.box.classList.remove('loading');
                    this.box.classList.add('failed');
                    this.box.title = `The 3-D view could not be shown: ${this.error}`;
                    console.error(`splinekit gallery: ${this.name}: ${this.error}`);
                }
            })();
            return this.whenReady;
        }

        setUp(gltf) {
            const spec = this.spec;
            this.gltf = gltf;
            const scene = new T.Scene();
            const bg = spec.background || [1, 1, 1];
            scene.background = new T.Color().setRGB(bg[0], bg[1], bg[2], T.SRGBColorSpace);
            scene.add(gltf.scene);
            this.widenLines(gltf.scene);
            const box = new T.Box3().setFromObject(gltf.scene);
            const centre = box.getCenter(new T.Vector3());
            const radius = Math.max(box.getSize(new T.Vector3()).length() / 2, 1e-6);

            const cam = spec.camera;
            const aspect = spec.size[0] / spec.size[1];
            const target = cam ? new T.Vector3(...cam.target) : centre.clone();
            let eye;
            if (cam) {
                eye = new T.Vector3(...cam.eye);
            } else {
                // The renderer's default: fitted, from azimuth 50°, elevation 28°.
                const az = (50 * Math.PI) / 180;
                const el = (28 * Math.PI) / 180;
                const dir = new T.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
                eye = centre.clone().addScaledVector(dir, radius / Math.sin((15 * Math.PI) / 180));
            }
            const reach = eye.distanceTo(centre) + radius;
            let camera;
            if (cam && cam.half_height) {
                const h = cam.half_height;
                camera = new T.OrthographicCamera(-h * aspect, h * aspect, h, -h, -10 * reach, 10 * reach);
            } else {
                camera = new T.PerspectiveCamera(cam ? cam.fov_y : 30, aspect, radius / 200, 100 * reach);
            }
            camera.up.set(...(cam ? cam.up : [0, 0, 1]));
            camera.position.copy(eye);
            camera.lookAt(target);
            // A light that turns with the camera, over a soft sky-and-ground light.
            const head = new T.DirectionalLight(0xffffff, 2.2);
            head.position.set(0.5, 1, 1);
            head.target.position.set(0, 0, -1);
            camera.add(head, head.target);
            scene.add(camera);
            scene.add(new T.HemisphereLight(0xffffff, 0x8c8c8c, 1.4));
            this.scene = scene;
            this.camera = camera;

            this.canvas = document.createElement('canvas');
            this.canvas.setAttribute('aria-label', `3-D view of ${this.name}: drag to turn, wheel to zoom, right-drag to pan`);
            this.context = this.canvas.getContext('2d');
            this.box.appendChild(this.canvas);
            const controls = new T.OrbitControls(camera, this.canvas);
            controls.target.copy(target);
            controls.maxDistance = 20 * reach;
            controls.update();
            controls.saveState();
            controls.addEventListener('change', () => this.invalidate());
            this.canvas.addEventListener('dblclick', () => controls.reset());
            this.controls = controls;
            new ResizeObserver(() => this.invalidate()).observe(this.canvas);

            if (gltf.animations.length > 0) {
                this.mixer = new T.AnimationMixer(gltf.scene);
                // The animation's period is the scene's: frames/fps (the last frame holds
                // for one frame's time before the loop starts again, as in the GIF).
                this.period = Math.max(spec.duration || 0, ...gltf.animations.map((c) => c.duration));
                for (const clip of gltf.animations) {
                    clip.duration = this.period;
                    this.mixer.clipAction(clip).setLoop(T.LoopRepeat, Infinity).play();
                }
                this.mixer.setTime(0);
                this.addTimeBar();
                // Animations play by themselves, unless the reader asked for less motion.
                if (window.matchMedia('(prefers-reduced-motion: reduce)').matches) {
                    this.pause();
                } else {
                    this.play();
                }
            }
        }

        /** A LineSegments2 over each line of the model (see the top of this file). */
        widenLines(root) {
            this.wideLines = [];
            const lines = [];
            root.traverse((o) => {
                if (o.isLine) {
                    lines.push(o);
                }
            });
            for (const line of lines) {
                const g = line.geometry;
                const count = g.index ? g.index.count : g.attributes.position.count;
                const vertex = (k) => (g.index ? g.index.getX(k) : k);
                // Segments as pairs of vertex numbers.
                const pairs = [];
                const step = line.isLineSegments ? 2 : 1;
                for (let k = 0; k + 1 < count; k += step) {
                    pairs.push(vertex(k), vertex(k + 1));
                }
                if (line.isLineLoop && count > 2) {
                    pairs.push(vertex(count - 1), vertex(0));
                }
                const geometry = new T.LineSegmentsGeometry();
                geometry.setPositions(new Float32Array(pairs.length * 3));
                const m = line.material;
                const material = new T.LineMaterial({
                    color: m.color,
                    linewidth: LINE_WIDTH,
                    transparent: m.transparent,
                    opacity: m.opacity,
                });
                const wide = new T.LineSegments2(geometry, material);
                wide.frustumCulled = false;
                line.add(wide);
                m.visible = false;
                this.wideLines.push({ line, wide, pairs, key: null });
            }
            this.updateWideLines();
        }

        /** Moves the wide lines' points to where the lines' morph targets put them. */
        updateWideLines() {
            for (const w of this.wideLines) {
                const g = w.line.geometry;
                const weights = w.line.morphTargetInfluences || [];
                const key = weights.join(',');
                if (key === w.key) {
                    continue;
                }
                w.key = key;
                const base = g.attributes.position;
                const targets = g.morphAttributes.position || [];
                const relative = g.morphTargetsRelative;
                const sum = relative ? 0 : weights.reduce((a, b) => a + b, 0);
                const buffer = w.wide.geometry.attributes.instanceStart.data;
                const out = buffer.array;
                w.pairs.forEach((v, i) => {
                    for (let c = 0; c < 3; c++) {
                        let x = base.getComponent(v, c) * (relative ? 1 : 1 - sum);
                        for (let t = 0; t < targets.length; t++) {
                            if (weights[t]) {
                                x += weights[t] * targets[t].getComponent(v, c);
                            }
                        }
                        out[3 * i + c] = x;
                    }
                });
                buffer.needsUpdate = true;
            }
        }

        addTimeBar() {
            const bar = this.figure.querySelector('.timebar');
            bar.hidden = false;
            this.button = bar.querySelector('button');
            this.slider = bar.querySelector('input');
            this.clock = bar.querySelector('output');
            this.slider.max = String(this.period);
            this.slider.step = String(this.period / 1000);
            this.button.addEventListener('click', () => (this.playing ? this.pause() : this.play()));
            this.slider.addEventListener('input', () => {
                this.pause();
                this.setTime(Number(this.slider.value));
            });
        }

        play() {
            if (this.setPlaying(true)) {
                requestFrame();
            }
        }

        pause() {
            this.setPlaying(false);
        }

        /**
         * Starts (true) or stops the animation and shows it on the button: it offers the
         * other action and is pressed while playing. False (nothing done) without one.
         */
        setPlaying(playing) {
            if (!this.mixer) {
                return false;
            }
            this.playing = playing;
            this.button.textContent = playing ? 'pause' : 'play';
            this.button.setAttribute('aria-pressed', String(playing));
            return true;
        }

        /** Shows the animation at time t (seconds, taken modulo the period). */
        setTime(t) {
            if (!this.mixer) {
                return;
            }
            this.time = ((t % this.period) + this.period) % this.period;
            this.mixer.setTime(this.time);
            this.slider.value = String(this.time);
            this.clock.textContent = formatTime(this.time);
            this.invalidate();
        }

        advance(dt) {
            this.setTime(this.time + dt);
        }

        /** The morph-target weights of the animated objects, by glTF node index. */
        influences() {
            const out = [];
            if (this.state !== 'ready') {
                return out;
            }
            this.gltf.scene.traverse((o) => {
                if (o.morphTargetInfluences) {
                    const a = this.gltf.parser.associations.get(o);
                    out.push({ node: a ? a.nodes : null, weights: Array.from(o.morphTargetInfluences) });
                }
            });
            return out;
        }

        invalidate() {
            this.dirty = true;
            requestFrame();
        }

        draw() {
            this.dirty = false;
            const dpr = Math.min(window.devicePixelRatio || 1, 2);
            const w = Math.max(1, Math.round(this.canvas.clientWidth * dpr));
            const h = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
            if (this.canvas.width !== w || this.canvas.height !== h) {
                this.canvas.width = w;
                this.canvas.height = h;
            }
            const aspect = w / h;
            const cam = this.camera;
            if (cam.isPerspectiveCamera) {
                cam.aspect = aspect;
            } else {
                const half = (cam.top - cam.bottom) / 2;
                cam.left = -half * aspect;
                cam.right = half * aspect;
            }
            cam.updateProjectionMatrix();
            this.updateWideLines();
            for (const wl of this.wideLines) {
                wl.wide.material.linewidth = LINE_WIDTH * dpr;
                wl.wide.material.resolution.set(w, h);
            }
            const r = renderer();
            r.setSize(w, h, false);
            r.render(this.scene, cam);
            this.context.drawImage(r.domElement, 0, 0);
        }
    }

    function start() {
        if (!T) {
            console.error('splinekit gallery: vendor/three-gltf-orbit.min.js did not load; the figures stay pictures');
            return;
        }
        const figures = document.querySelectorAll('figure[data-view]');
        const byFigure = new Map();
        for (const figure of figures) {
            const view = new View(figure);
            gallery.views.push(view);
            byFigure.set(figure, view);
        }
        const observer = new IntersectionObserver(
            (entries) => {
                for (const entry of entries) {
                    const view = byFigure.get(entry.target);
                    view.visible = entry.isIntersecting;
                    if (view.visible) {
                        view.load();
                        view.invalidate();
                    }
                }
            },
            { rootMargin: '200px' },
        );
        for (const figure of figures) {
            observer.observe(figure);
        }
    }

    if (document.readyState === 'loading') {
        document.addEventListener('DOMContentLoaded', start);
    } else {
        start();
    }
})();
