//! Which graphics backends wgpu may use, and the one environment setting headless Vulkan
//! needs to stay quiet.
//!
//! Both the offscreen renderer and the studio's window try Vulkan and GL, or what
//! `WGPU_BACKEND` names (`gl`, `vulkan`, a comma list: wgpu's own variable), so that CI can
//! run the rendering tests on each of Mesa's software drivers: llvmpipe through EGL (GL)
//! and lavapipe (Vulkan).
//!
//! Mesa's Vulkan driver package installs an implicit layer, `VK_LAYER_MESA_device_select`,
//! which, when an application enables the Wayland surface extension (wgpu enables every
//! window-system extension the loader offers), asks the Wayland compositor which GPU drives
//! the display. On a machine without a Wayland session (a server, a container, CI, an SSH
//! login) `XDG_RUNTIME_DIR` is unset, and libwayland prints
//! `error: XDG_RUNTIME_DIR is invalid or not set in the environment.` to standard error at
//! every device enumeration: twice a picture, though the picture is fine. There the layer
//! can learn nothing from Wayland; [`prepare_headless_environment`] turns it off with its
//! own switch (`NODEVICE_SELECT=1`, from the layer's manifest), and wgpu's power
//! preference picks the adapter as it does without the layer.

/// The backends to try: `WGPU_BACKEND` if set (wgpu's comma list, e.g. `gl` or `vulkan`),
/// else Vulkan and GL.
pub fn backends() -> wgpu::Backends {
    wgpu::Backends::from_env().unwrap_or(wgpu::Backends::VULKAN | wgpu::Backends::GL)
}

/// Whether libwayland could reach a compositor: `WAYLAND_SOCKET` names an open socket, or
/// `WAYLAND_DISPLAY` is an absolute path, or `XDG_RUNTIME_DIR` is an absolute path (the
/// directory of the display's socket). Without any of these, `wl_display_connect` prints
/// its `XDG_RUNTIME_DIR` error and fails.
fn wayland_reachable(var: impl Fn(&str) -> Option<String>) -> bool {
    let absolute = |name: &str| var(name).is_some_and(|v| v.starts_with('/'));
    var("WAYLAND_SOCKET").is_some() || absolute("WAYLAND_DISPLAY") || absolute("XDG_RUNTIME_DIR")
}

/// The variables to set before the first Vulkan instance so that Mesa's device-selection
/// layer does not print libwayland's error (see the module): `NODEVICE_SELECT=1` when no
/// Wayland compositor is reachable and the user has not chosen a device through the layer
/// (`MESA_VK_DEVICE_SELECT`, `DRI_PRIME`) or set `NODEVICE_SELECT` either way.
fn headless_settings(var: impl Fn(&str) -> Option<String>) -> Vec<(&'static str, &'static str)> {
    let chosen = ["NODEVICE_SELECT", "MESA_VK_DEVICE_SELECT", "DRI_PRIME"].iter().any(|name| var(name).is_some());
    if chosen || wayland_reachable(&var) { Vec::new() } else { vec![("NODEVICE_SELECT", "1")] }
}

/// Turns Mesa's Vulkan device-selection layer off where it could only print libwayland's
/// `XDG_RUNTIME_DIR` error (no Wayland session; see the module), so that offscreen
/// rendering and the studio print nothing but their own messages on every backend.
///
/// It sets a process environment variable, which the Vulkan loader reads when wgpu creates
/// its instance: call it at the start of `main` (the `splinekit` binary does; the Python
/// package does the same in Python when it is imported).
///
/// # Safety
///
/// As [`std::env::set_var`]: no other thread may read or write the environment meanwhile
/// (true at the start of `main`, before any thread is spawned).
pub unsafe fn prepare_headless_environment() {
    for (name, value) in headless_settings(|name| std::env::var(name).ok()) {
        // SAFETY: the caller guarantees that no other thread uses the environment.
        unsafe { std::env::set_var(name, value) };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(pairs: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let pairs: Vec<(String, String)> = pairs.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
        move |name| pairs.iter().find(|(k, _)| k == name).map(|(_, v)| v.clone())
    }

    #[test]
    fn the_layer_is_turned_off_only_without_a_wayland_session_or_a_choice() {
        let off = vec![("NODEVICE_SELECT", "1")];
        assert_eq!(headless_settings(env(&[])), off);
        assert_eq!(headless_settings(env(&[("XDG_RUNTIME_DIR", "")])), off);
        assert_eq!(headless_settings(env(&[("XDG_RUNTIME_DIR", "relative/dir")])), off);
        assert_eq!(headless_settings(env(&[("DISPLAY", ":99")])), off);
        assert!(headless_settings(env(&[("XDG_RUNTIME_DIR", "/run/user/1000")])).is_empty());
        assert!(headless_settings(env(&[("WAYLAND_DISPLAY", "/tmp/wayland-1")])).is_empty());
        assert!(headless_settings(env(&[("WAYLAND_SOCKET", "3")])).is_empty());
        for chosen in ["NODEVICE_SELECT", "MESA_VK_DEVICE_SELECT", "DRI_PRIME"] {
            assert!(headless_settings(env(&[(chosen, "0")])).is_empty(), "{chosen}");
        }
    }
}
