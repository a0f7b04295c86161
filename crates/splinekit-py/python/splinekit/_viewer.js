/* splinekit's notebook views: each shows one glb (base64) with three.js, turned by the
 * mouse, animations played with a play/pause button and a time slider.
 *
 * Adapted from the gallery's viewer (crates/splinekit-cli/src/gallery/viewer.js): the
 * pinned three.js bundle defines the global SplinekitThree (the first view of a session
 * embeds it, later ones reuse it); one WebGL renderer draws every view into the view's
 * own 2-D canvas, so a notebook of many views holds one WebGL context; lines are drawn by
 * three's screen-space wide lines (WebGL draws one-pixel lines), following the morph
 * targets of an animation. This file defines window.splinekitNotebook once; each view's
 * cell calls splinekitNotebook.show(id, base64, spec).
 *
 * window.splinekitNotebook.views lists the views for tests: state ('loading', 'ready',
 * 'error'), error, drawn() (pixels that differ from the background), play(), pause().
 */
(function () {
    'use strict';
    if (window.splinekitNotebook) {
        return;
    }
    const LINE_WIDTH = 2.5;
    const notebook = { views: [], show };
    window.splinekitNotebook = notebook;

    let sharedRenderer = null;
    function renderer(T) {
        if (!sharedRenderer) {
            sharedRenderer = new T.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
            sharedRenderer.setPixelRatio(1);
        }
        return sharedRenderer;
    }

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
        for (const view of notebook.views) {
            if (view.state !== 'ready') {
                continue;
            }
            if (view.playing) {
                view.setTime(view.time + dt);
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

    function bytesOf(base64) {
        const text = atob(base64);
        const bytes = new Uint8Array(text.length);
        for (let i = 0; i < text.length; i++) {
            bytes[i] = text.charCodeAt(i);
        }
        return bytes.buffer;
    }

    class View {
        constructor(box, spec) {
            this.box = box;
            this.spec = spec;
            this.state = 'loading';
            this.error = null;
            this.dirty = false;
            this.playing = false;
            this.time = 0;
            this.period = 0;
        }

        async load(T, base64) {
            try {
                const gltf = await new T.GLTFLoader().parseAsync(bytesOf(base64), '');
                this.setUp(T, gltf);
                this.state = 'ready';
                this.invalidate();
            } catch (e) {
                this.fail(String(e && e.message ? e.message : e));
            }
        }

        fail(message) {
            this.state = 'error';
            this.error = message;
            const note = document.createElement('p');
            note.textContent = `splinekit: the 3-D view could not be shown (${message})`;
            this.box.appendChild(note);
        }

        setUp(T, gltf) {
            const spec = this.spec;
            this.T = T;
            this.gltf = gltf;
            const scene = new T.Scene();
            const bg = spec.background || [1, 1, 1];
            scene.background = new T.Color().setRGB(bg[0], bg[1], bg[2], T.SRGBColorSpace);
            scene.add(gltf.scene);
            this.widenLines(T, gltf.scene);
            const box = new T.Box3().setFromObject(gltf.scene);
            const centre = box.getCenter(new T.Vector3());
            const extent = box.getSize(new T.Vector3());
            const radius = Math.max(extent.length() / 2, 1e-6);
            // Flat in z (plane curves, a scene in one plane z = const): from the top, as
            // the renderer draws it; else from azimuth 50°, elevation 28°.
            const flat = extent.z <= 1e-9 * Math.max(radius, 1);
            let dir;
            if (flat) {
                dir = new T.Vector3(0, 0, 1);
            } else {
                const az = (50 * Math.PI) / 180;
                const el = (28 * Math.PI) / 180;
                dir = new T.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
            }
            const distance = radius / Math.sin((15 * Math.PI) / 180);
            const eye = centre.clone().addScaledVector(dir, distance);
            const camera = new T.PerspectiveCamera(30, spec.size[0] / spec.size[1], radius / 200, 100 * (distance + radius));
            camera.up.set(...(flat ? [0, 1, 0] : [0, 0, 1]));
            camera.position.copy(eye);
            camera.lookAt(centre);
            const head = new T.DirectionalLight(0xffffff, 2.2);
            head.position.set(0.5, 1, 1);
            head.target.position.set(0, 0, -1);
            camera.add(head, head.target);
            scene.add(camera);
            scene.add(new T.HemisphereLight(0xffffff, 0x8c8c8c, 1.4));
            this.scene = scene;
            this.camera = camera;

            this.canvas = this.box.querySelector('canvas');
            this.context = this.canvas.getContext('2d', { willReadFrequently: true });
            const controls = new T.OrbitControls(camera, this.canvas);
            controls.target.copy(centre);
            controls.update();
            controls.saveState();
            controls.addEventListener('change', () => this.invalidate());
            this.canvas.addEventListener('dblclick', () => controls.reset());
            this.controls = controls;
            if (typeof ResizeObserver !== 'undefined') {
                new ResizeObserver(() => this.invalidate()).observe(this.canvas);
            }
            if (gltf.animations.length > 0) {
                this.mixer = new T.AnimationMixer(gltf.scene);
                this.period = Math.max(spec.duration || 0, ...gltf.animations.map((c) => c.duration));
                for (const clip of gltf.animations) {
                    clip.duration = this.period;
                    this.mixer.clipAction(clip).setLoop(T.LoopRepeat, Infinity).play();
                }
                this.mixer.setTime(0);
                this.addTimeBar();
                this.play();
            }
        }

        widenLines(T, root) {
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
                const material = new T.LineMaterial({ color: m.color, linewidth: LINE_WIDTH, transparent: m.transparent, opacity: m.opacity });
                const wide = new T.LineSegments2(geometry, material);
                wide.frustumCulled = false;
                line.add(wide);
                m.visible = false;
                this.wideLines.push({ line, wide, pairs, key: null });
            }
            this.updateWideLines();
        }

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
            const bar = this.box.querySelector('.splinekit-timebar');
            bar.style.display = 'flex';
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
            if (this.mixer) {
                this.playing = true;
                this.button.textContent = 'pause';
                requestFrame();
            }
        }

        pause() {
            if (this.mixer) {
                this.playing = false;
                this.button.textContent = 'play';
            }
        }

        setTime(t) {
            if (!this.mixer) {
                return;
            }
            this.time = ((t % this.period) + this.period) % this.period;
            this.mixer.setTime(this.time);
            this.slider.value = String(this.time);
            this.clock.textContent = `${this.time.toFixed(2)} s`;
            this.invalidate();
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
            this.camera.aspect = w / h;
            this.camera.updateProjectionMatrix();
            this.updateWideLines();
            for (const wl of this.wideLines) {
                wl.wide.material.linewidth = LINE_WIDTH * dpr;
                wl.wide.material.resolution.set(w, h);
            }
            const r = renderer(this.T);
            r.setSize(w, h, false);
            r.render(this.scene, this.camera);
            this.context.drawImage(r.domElement, 0, 0);
        }

        /** Pixels of the canvas that differ from the background (for tests). */
        drawn() {
            if (this.state !== 'ready') {
                return 0;
            }
            this.draw();
            const { width, height } = this.canvas;
            const data = this.context.getImageData(0, 0, width, height).data;
            const bg = (this.spec.background || [1, 1, 1]).map((c) => Math.round(255 * c));
            let count = 0;
            for (let i = 0; i < data.length; i += 4) {
                if (Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]) > 24) {
                    count++;
                }
            }
            return count;
        }
    }

    /** Shows the glb (base64) in the element with this id, once three.js is there. */
    function show(id, base64, spec) {
        const box = document.getElementById(id);
        if (!box || box.dataset.splinekitShown) {
            return;
        }
        box.dataset.splinekitShown = '1';
        const view = new View(box, spec);
        notebook.views.push(view);
        let tries = 0;
        const start = () => {
            const T = window.SplinekitThree;
            if (T) {
                view.load(T, base64);
            } else if (tries++ < 100) {
                setTimeout(start, 50);
            } else {
                view.fail('three.js is not loaded: show the first view of the session again, or call splinekit.set_display(embed_three="always")');
            }
        };
        start();
    }
})();
