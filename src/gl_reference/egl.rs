//! The EGL side: the library opened at run time, the display and device, a desktop-GL
//! compatibility context current without a surface, and the framebuffer object it renders
//! into. Each is owned and freed in `Drop`, in the reverse order of its making.
//!
//! Displays are tried in this order: every `EGL_EXT_platform_device` device (software devices
//! first when [`GlOptions::prefer_software`] says so), then `EGL_MESA_platform_surfaceless`.
//! The first display whose context works, and which is the device [`GlOptions`] asks for, is
//! used. Neither platform needs a window system, so this runs on headless machines.

use std::ffi::{c_char, c_void, CStr};

use khronos_egl as khr;

use super::bindings::{self, Gl};
use super::error::{DrawError, GlError, NoDriver};
use super::GlOptions;

/// EGL 1.4 is what this module calls: eglBindAPI (1.2) and eglMakeCurrent without surfaces
/// (with EGL_KHR_surfaceless_context); 1.5's eglGetPlatformDisplay comes through the EXT name.
type Egl = khr::DynamicInstance<khr::EGL1_4>;

/// The name `dlopen` searches for: glvnd's dispatcher on Linux, which picks the vendor
/// libraries (Mesa, NVIDIA) from `/usr/share/glvnd/egl_vendor.d`.
const DEFAULT_LIBRARY: &str = "libEGL.so.1";

// Extension tokens this module uses that khronos-egl does not name (values from Khronos' EGL
// registry).
const PLATFORM_DEVICE_EXT: khr::Enum = 0x313F;
const PLATFORM_SURFACELESS_MESA: khr::Enum = 0x31DD;
const DRM_DEVICE_FILE_EXT: khr::Int = 0x3233;
const DEVICE_UUID_EXT: khr::Int = 0x335C;
const RENDERER_EXT: khr::Int = 0x335F;

/// eglQueryDevicesEXT (EGL_EXT_device_enumeration).
type QueryDevicesFn = unsafe extern "system" fn(khr::Int, *mut DeviceHandle, *mut khr::Int) -> khr::Boolean;
/// eglQueryDeviceStringEXT (EGL_EXT_device_query).
type QueryDeviceStringFn = unsafe extern "system" fn(DeviceHandle, khr::Int) -> *const c_char;
/// eglQueryDeviceBinaryEXT (EGL_EXT_device_persistent_id).
type QueryDeviceBinaryFn =
    unsafe extern "system" fn(DeviceHandle, khr::Int, khr::Int, *mut c_void, *mut khr::Int) -> khr::Boolean;
/// eglGetPlatformDisplayEXT (EGL_EXT_platform_base).
type GetPlatformDisplayFn =
    unsafe extern "system" fn(khr::Enum, *mut c_void, *const khr::Int) -> khr::EGLDisplay;

/// An `EGLDeviceEXT`: owned by the EGL implementation for the life of the library, never
/// freed by its user.
type DeviceHandle = *mut c_void;

/// An EGL extension's entry point by name, typed as its specification spells it; `None` where
/// the library has none.
macro_rules! entry_point {
    ($egl:expr, $name:literal, $type:ty) => {
        $egl.get_proc_address($name).map(|f| {
            // SAFETY: eglGetProcAddress returned the entry point of this name, whose C
            // signature its extension's specification gives and `$type` spells; both sides
            // are function pointers of the same size.
            unsafe { std::mem::transmute::<extern "system" fn(), $type>(f) }
        })
    };
}

/// Whether `name` is one of the space-separated names in `list` (an EGL or GL extension
/// string).
pub(super) fn has_extension(list: &str, name: &str) -> bool {
    list.split_ascii_whitespace().any(|e| e == name)
}

/// Runs `f` with a fresh desktop-GL compatibility context current on this thread and a
/// `width` x `height` framebuffer object bound for drawing and reading, then frees all of it.
/// `f` gets the loaded entry points and a description of the platform and device.
pub(super) fn with_context<T>(
    options: &GlOptions,
    width: u32,
    height: u32,
    f: impl FnOnce(&Gl, &str) -> Result<T, GlError>,
) -> Result<T, GlError> {
    if width == 0 || height == 0 {
        return Err(GlError::Size {
            width,
            height,
            problem: "empty".into(),
        });
    }
    let library = Library::open(options)?;
    let (session, gl) = library.open_session(options)?;
    let framebuffer = Framebuffer::new(&gl, width, height)?;
    let result = f(&gl, &session.description);
    // The framebuffer's names belong to the context: delete them while it is current.
    drop(framebuffer);
    drop(session);
    result
}

/// The EGL library, its client extensions and the entry points of the device extensions.
struct Library {
    egl: Egl,
    client_extensions: String,
    get_platform_display: Option<GetPlatformDisplayFn>,
    query_devices: Option<QueryDevicesFn>,
    query_device_string: Option<QueryDeviceStringFn>,
    query_device_binary: Option<QueryDeviceBinaryFn>,
}

/// A display to try, and what is known about its device before a context exists.
struct Candidate {
    platform: khr::Enum,
    /// The EGLDeviceEXT for the device platform; null for surfaceless.
    device: DeviceHandle,
    description: String,
    software: bool,
    uuid: Option<[u8; 16]>,
    /// EGL_RENDERER_EXT, where the device reports it.
    name: Option<String>,
}

/// What a candidate's context turned out to be, against what [`GlOptions`] asks for.
enum Match {
    Yes,
    No(String),
}

impl Library {
    fn open(options: &GlOptions) -> Result<Library, NoDriver> {
        let name = options
            .egl_library
            .as_deref()
            .map_or_else(|| DEFAULT_LIBRARY.into(), |p| p.as_os_str().to_os_string());
        // SAFETY: the library is EGL's (libEGL.so.1 or one the caller names, whose contract
        // is EGL's); khronos-egl resolves EGL 1.0-1.4's entry points by name and fails if one
        // is missing. It loads with RTLD_NODELETE, so function pointers handed out by the
        // library (eglGetProcAddress) stay valid after `egl` drops.
        let egl = unsafe { Egl::load_required_from_filename(&name) }.map_err(|source| NoDriver::Library {
            library: name.to_string_lossy().into_owned(),
            source,
        })?;
        // EGL_EXT_client_extensions: EGL_NO_DISPLAY's extension string; an error if the
        // library has no client extensions at all, which leaves no platform to use.
        let client_extensions = egl
            .query_string(None, khr::EXTENSIONS)
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        if client_extensions.trim().is_empty() {
            // glvnd's libEGL answers this itself only with a vendor library behind it.
            return Err(NoDriver::NoVendor {
                library: name.to_string_lossy().into_owned(),
            });
        }
        let has = |name: &str| has_extension(&client_extensions, name);
        let get_platform_display = if has("EGL_EXT_platform_base") {
            entry_point!(egl, "eglGetPlatformDisplayEXT", GetPlatformDisplayFn)
        } else {
            None
        };
        let query_devices = if has("EGL_EXT_device_enumeration") || has("EGL_EXT_device_base") {
            entry_point!(egl, "eglQueryDevicesEXT", QueryDevicesFn)
        } else {
            None
        };
        let query_device_string = if has("EGL_EXT_device_query") || has("EGL_EXT_device_base") {
            entry_point!(egl, "eglQueryDeviceStringEXT", QueryDeviceStringFn)
        } else {
            None
        };
        // A device-level extension: present in the library whenever one of its vendors has it;
        // each device says for itself whether it answers (its own extension string).
        let query_device_binary = entry_point!(egl, "eglQueryDeviceBinaryEXT", QueryDeviceBinaryFn);
        Ok(Library {
            egl,
            client_extensions,
            get_platform_display,
            query_devices,
            query_device_string,
            query_device_binary,
        })
    }

    /// The displays to try, in order.
    fn candidates(&self, options: &GlOptions) -> Result<Vec<Candidate>, NoDriver> {
        let has = |name: &str| has_extension(&self.client_extensions, name);
        let no_platform = || NoDriver::NoPlatform {
            extensions: self.client_extensions.clone(),
        };
        if self.get_platform_display.is_none() {
            return Err(no_platform());
        }
        let mut candidates = Vec::new();
        if has("EGL_EXT_platform_device") {
            if let Some(query_devices) = self.query_devices {
                candidates.extend(self.devices(query_devices));
            }
        }
        if options.prefer_software {
            // Stable: each group keeps EGL's order.
            candidates.sort_by_key(|c| !c.software);
        }
        if has("EGL_MESA_platform_surfaceless") {
            candidates.push(Candidate {
                platform: PLATFORM_SURFACELESS_MESA,
                device: std::ptr::null_mut(),
                description: "EGL_MESA_platform_surfaceless".into(),
                software: false,
                uuid: None,
                name: None,
            });
        }
        if candidates.is_empty() && !has("EGL_EXT_platform_device") {
            return Err(no_platform());
        }
        Ok(candidates)
    }

    /// Every EGL device, described with what its extensions let it say about itself.
    fn devices(&self, query_devices: QueryDevicesFn) -> Vec<Candidate> {
        let mut count: khr::Int = 0;
        // SAFETY: with a null array, eglQueryDevicesEXT writes only the device count.
        let ok = unsafe { query_devices(0, std::ptr::null_mut(), &mut count) };
        if ok != khr::TRUE || count <= 0 {
            return Vec::new();
        }
        let mut devices: Vec<DeviceHandle> = vec![std::ptr::null_mut(); count as usize];
        // SAFETY: `devices` has room for `count` handles, and the call writes at most that
        // many and their number into `count`.
        let ok = unsafe { query_devices(count, devices.as_mut_ptr(), &mut count) };
        if ok != khr::TRUE {
            return Vec::new();
        }
        devices.truncate(count.max(0) as usize);
        let total = devices.len();
        devices
            .into_iter()
            .enumerate()
            .map(|(index, device)| {
                let extensions = self.device_string(device, khr::EXTENSIONS).unwrap_or_default();
                let has = |name: &str| has_extension(&extensions, name);
                let software = has("EGL_MESA_device_software");
                let name = has("EGL_EXT_device_query_name")
                    .then(|| self.device_string(device, RENDERER_EXT))
                    .flatten();
                let uuid = has("EGL_EXT_device_persistent_id")
                    .then(|| self.device_uuid(device))
                    .flatten();
                let drm_file = has("EGL_EXT_device_drm")
                    .then(|| self.device_string(device, DRM_DEVICE_FILE_EXT))
                    .flatten();
                let what = match (&name, &drm_file) {
                    (Some(name), Some(file)) => format!("{name}, {file}"),
                    (Some(name), None) => name.clone(),
                    (None, Some(file)) => file.clone(),
                    (None, None) if software => "EGL_MESA_device_software".into(),
                    (None, None) => "unnamed".into(),
                };
                Candidate {
                    platform: PLATFORM_DEVICE_EXT,
                    device,
                    description: format!("EGL_EXT_platform_device (device {index} of {total}: {what})"),
                    software,
                    uuid,
                    name,
                }
            })
            .collect()
    }

    fn device_string(&self, device: DeviceHandle, name: khr::Int) -> Option<String> {
        let query = self.query_device_string?;
        // SAFETY: `device` came from eglQueryDevicesEXT; the result is NULL or a
        // NUL-terminated string the implementation owns.
        let text = unsafe { query(device, name) };
        if text.is_null() {
            return None;
        }
        // SAFETY: non-NULL and NUL-terminated (above); copied before the next EGL call.
        Some(unsafe { CStr::from_ptr(text) }.to_string_lossy().into_owned())
    }

    fn device_uuid(&self, device: DeviceHandle) -> Option<[u8; 16]> {
        let query = self.query_device_binary?;
        let mut uuid = [0u8; 16];
        let mut size: khr::Int = 0;
        // SAFETY: `device` came from eglQueryDevicesEXT; the call writes at most 16 bytes (the
        // size given) into `uuid` and their number into `size`.
        let ok = unsafe { query(device, DEVICE_UUID_EXT, 16, uuid.as_mut_ptr().cast(), &mut size) };
        (ok == khr::TRUE && size == 16).then_some(uuid)
    }

    /// The first candidate that gives a working context and is the device `options` asks
    /// for, current on this thread, with its GL entry points.
    fn open_session(&self, options: &GlOptions) -> Result<(Session<'_>, Gl), GlError> {
        let candidates = self.candidates(options)?;
        let wanted = wanted(options);
        let mut tried = Vec::new();
        // Whether some device exists but is not the one asked for: then the answer is "no
        // such device", not "no GL driver".
        let mut another_device = false;
        for candidate in &candidates {
            // What is known before a context exists rules a device out early.
            if let Match::No(why) = pre_match(candidate, options) {
                tried.push(format!("{}: {why}", candidate.description));
                another_device = true;
                continue;
            }
            let (session, gl) = match self.try_open(candidate) {
                Ok(opened) => opened,
                Err(why) => {
                    tried.push(format!("{}: {why}", candidate.description));
                    continue;
                }
            };
            match post_match(&gl, candidate, options) {
                Match::Yes => return Ok((session, gl)),
                Match::No(why) => {
                    tried.push(format!("{}: {why}", candidate.description));
                    another_device = true;
                }
            }
        }
        if tried.is_empty() {
            tried.push("EGL_EXT_platform_device lists no devices".into());
        }
        match wanted {
            Some(wanted) if another_device => Err(GlError::NoMatchingDevice { wanted, tried }),
            _ => Err(NoDriver::NoContext { tried }.into()),
        }
    }

    /// Initializes the candidate's display and makes a compatibility context current on it;
    /// the error says which step failed.
    fn try_open(&self, candidate: &Candidate) -> Result<(Session<'_>, Gl), String> {
        let get_platform_display = self.get_platform_display.ok_or("no eglGetPlatformDisplayEXT")?;
        let attributes = [khr::NONE];
        // SAFETY: the platform is one the client extensions list, with its native display:
        // an EGLDeviceEXT from eglQueryDevicesEXT for the device platform, and
        // EGL_DEFAULT_DISPLAY (null) for surfaceless, as their specifications require; the
        // attribute list is EGL_NONE-terminated.
        let raw = unsafe { get_platform_display(candidate.platform, candidate.device, attributes.as_ptr()) };
        if raw == khr::NO_DISPLAY {
            return Err(format!(
                "eglGetPlatformDisplayEXT failed ({})",
                egl_error(&self.egl)
            ));
        }
        // SAFETY: a display the implementation just returned.
        let display = unsafe { khr::Display::from_ptr(raw) };
        let (major, minor) = self
            .egl
            .initialize(display)
            .map_err(|e| format!("eglInitialize failed ({})", error_name(e)))?;
        // From here on the session owns the display and terminates it when dropped.
        let mut session = Session {
            egl: &self.egl,
            display,
            context: None,
            current: false,
            description: candidate.description.clone(),
        };
        let query = |name| {
            self.egl
                .query_string(Some(display), name)
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        let extensions = query(khr::EXTENSIONS);
        let apis = query(khr::CLIENT_APIS);
        if !apis.split_ascii_whitespace().any(|api| api == "OpenGL") {
            return Err(format!(
                "EGL {major}.{minor} display without desktop OpenGL (client APIs: {apis:?})"
            ));
        }
        if !has_extension(&extensions, "EGL_KHR_surfaceless_context") {
            return Err("no EGL_KHR_surfaceless_context (a context without a surface)".into());
        }
        self.egl
            .bind_api(khr::OPENGL_API)
            .map_err(|e| format!("eglBindAPI(EGL_OPENGL_API) failed ({})", error_name(e)))?;
        let config = if has_extension(&extensions, "EGL_KHR_no_config_context") {
            // SAFETY: EGL_NO_CONFIG_KHR is the null config, which EGL_KHR_no_config_context
            // accepts for a context that is only ever made current without a surface.
            unsafe { khr::Config::from_ptr(std::ptr::null_mut()) }
        } else {
            let wanted = [
                khr::RENDERABLE_TYPE,
                khr::OPENGL_BIT,
                // The default would be EGL_WINDOW_BIT, which headless displays lack.
                khr::SURFACE_TYPE,
                khr::DONT_CARE,
                khr::NONE,
            ];
            self.egl
                .choose_first_config(display, &wanted)
                .map_err(|e| format!("eglChooseConfig failed ({})", error_name(e)))?
                .ok_or("no EGLConfig renders desktop OpenGL")?
        };
        // A 2.1 request in the compatibility profile: the driver gives its newest version
        // that keeps the fixed-function pipeline (Mesa: 4.5 compatibility). The profile bit
        // matters only from 3.2 on, but says what is meant. Without EGL 1.5 or
        // EGL_KHR_create_context these attributes do not exist, and the default context is
        // a compatibility one anyway.
        let versioned = (major, minor) >= (1, 5) || has_extension(&extensions, "EGL_KHR_create_context");
        let attributes: &[khr::Int] = if versioned {
            &[
                khr::CONTEXT_MAJOR_VERSION,
                2,
                khr::CONTEXT_MINOR_VERSION,
                1,
                khr::CONTEXT_OPENGL_PROFILE_MASK,
                khr::CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                khr::NONE,
            ]
        } else {
            &[khr::NONE]
        };
        let context = self
            .egl
            .create_context(display, config, None, attributes)
            .map_err(|e| {
                format!(
                    "eglCreateContext (OpenGL 2.1, compatibility) failed ({})",
                    error_name(e)
                )
            })?;
        session.context = Some(context);
        self.egl
            .make_current(display, None, None, Some(context))
            .map_err(|e| format!("eglMakeCurrent without a surface failed ({})", error_name(e)))?;
        session.current = true;
        let gl = Gl::load_with(|name| {
            self.egl
                .get_proc_address(name)
                .map_or(std::ptr::null(), |f| f as *const c_void)
        });
        Ok((session, gl))
    }
}

/// What [`GlOptions`] asks for, in words; `None` for any device.
fn wanted(options: &GlOptions) -> Option<String> {
    let uuid = options.vulkan_uuid.map(|u| format!("UUID {}", hex(&u)));
    let name = options.vulkan_name.as_ref().map(|n| format!("name {n:?}"));
    match (uuid, name) {
        (Some(u), Some(n)) => Some(format!("the Vulkan device with {u} or {n}")),
        (Some(u), None) => Some(format!("the Vulkan device with {u}")),
        (None, Some(n)) => Some(format!("the Vulkan device with {n}")),
        (None, None) => None,
    }
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn name_matches(name: &str, wanted: &str) -> bool {
    name.to_lowercase().contains(&wanted.to_lowercase())
}

/// Matching on what the device says about itself before a context exists: its UUID decides
/// where both sides have one, then EGL_RENDERER_EXT; otherwise it waits for GL_RENDERER.
fn pre_match(candidate: &Candidate, options: &GlOptions) -> Match {
    match (options.vulkan_uuid, candidate.uuid) {
        (Some(wanted), Some(uuid)) if wanted == uuid => return Match::Yes,
        (Some(_), Some(uuid)) => return Match::No(format!("UUID {} differs", hex(&uuid))),
        _ => {}
    }
    match (&options.vulkan_name, &candidate.name) {
        (Some(wanted), Some(name)) if !name_matches(name, wanted) => {
            Match::No(format!("EGL_RENDERER_EXT {name:?} differs"))
        }
        _ => Match::Yes,
    }
}

/// Matching once the context is current: a UUID match was already decided, so a device with
/// a UUID is settled; a device without one is matched by GL_RENDERER when a name is given.
fn post_match(gl: &Gl, candidate: &Candidate, options: &GlOptions) -> Match {
    if options.vulkan_uuid.is_some() && candidate.uuid.is_some() {
        return Match::Yes;
    }
    match &options.vulkan_name {
        Some(wanted) => {
            let renderer = gl_string(gl, bindings::RENDERER).unwrap_or_default();
            if name_matches(&renderer, wanted) {
                Match::Yes
            } else {
                Match::No(format!("GL_RENDERER {renderer:?} differs"))
            }
        }
        None if options.vulkan_uuid.is_some() => Match::No("reports no device UUID".into()),
        None => Match::Yes,
    }
}

/// The leading "major.minor" of a GL_VERSION string ((0, 0) where it has none).
pub(super) fn version_number(version: &str) -> (u32, u32) {
    let mut numbers = version
        .split(|c: char| !c.is_ascii_digit())
        .map(|n| n.parse().unwrap_or(0));
    (numbers.next().unwrap_or(0), numbers.next().unwrap_or(0))
}

/// glGetString of the current context.
pub(super) fn gl_string(gl: &Gl, name: bindings::types::GLenum) -> Result<String, GlError> {
    // SAFETY: a context is current on this thread; glGetString returns a static
    // NUL-terminated string or NULL.
    let s = unsafe { gl.GetString(name) };
    if s.is_null() {
        return Err(GlError::NullString(name));
    }
    // SAFETY: non-NULL, NUL-terminated, owned by the GL implementation.
    let text = unsafe { CStr::from_ptr(s.cast::<c_char>()) };
    Ok(text.to_string_lossy().into_owned())
}

fn error_name(error: khr::Error) -> String {
    format!("{error:?}, 0x{:04X}", error.native())
}

/// The calling thread's EGL error, for calls that do not return one themselves.
fn egl_error(egl: &Egl) -> String {
    egl.get_error()
        .map_or_else(|| "no EGL error recorded".into(), error_name)
}

/// An initialized display, and the context made on it once there is one. Dropping it
/// unbinds, destroys and terminates, in that order, and releases the thread's EGL state.
struct Session<'l> {
    egl: &'l Egl,
    display: khr::Display,
    context: Option<khr::Context>,
    /// Whether `context` is current on this thread.
    current: bool,
    /// The platform and device, for [`super::GlInfo::created_with`].
    description: String,
}

impl Drop for Session<'_> {
    fn drop(&mut self) {
        // Errors are ignored: nothing is left to do about them, and each step only frees.
        if self.current {
            let _ = self.egl.make_current(self.display, None, None, None);
        }
        if let Some(context) = self.context.take() {
            let _ = self.egl.destroy_context(self.display, context);
        }
        // The reference is the only user of the displays it opens: terminating frees the
        // driver's resources (llvmpipe's rasterizer threads among them) now rather than at
        // exit. Mesa 22.3 keeps about 4 KiB per initialize/terminate cycle (measured: 400 KiB
        // over 100 renders; flat without the terminate), the price of a fresh start each time.
        let _ = self.egl.terminate(self.display);
        let _ = self.egl.release_thread();
    }
}

/// A framebuffer object with an RGBA8 color and a 24-bit depth renderbuffer, no
/// multisampling, bound for drawing and reading. Dropping it unbinds and deletes all three
/// (the context that made them must still be current).
struct Framebuffer<'g> {
    gl: &'g Gl,
    framebuffer: bindings::types::GLuint,
    renderbuffers: [bindings::types::GLuint; 2],
}

impl<'g> Framebuffer<'g> {
    fn new(gl: &'g Gl, width: u32, height: u32) -> Result<Framebuffer<'g>, GlError> {
        let version = gl_string(gl, bindings::VERSION)?;
        if version_number(&version).0 < 3 {
            let extensions = gl_string(gl, bindings::EXTENSIONS)?;
            if !has_extension(&extensions, "GL_ARB_framebuffer_object")
                && !has_extension(&extensions, "GL_EXT_framebuffer_object")
            {
                return Err(GlError::NoFramebufferObjects { version });
            }
        }
        let too_large = |problem: String| GlError::Size {
            width,
            height,
            problem,
        };
        let mut max_size: bindings::types::GLint = 0;
        // SAFETY: a context is current on this thread; one GLint is written.
        unsafe { gl.GetIntegerv(bindings::MAX_RENDERBUFFER_SIZE, &mut max_size) };
        let max = u32::try_from(max_size).unwrap_or(0);
        if width > max || height > max {
            return Err(too_large(format!(
                "larger than this GL's GL_MAX_RENDERBUFFER_SIZE, {max}"
            )));
        }
        // Within GL_MAX_RENDERBUFFER_SIZE, which is far below i32::MAX.
        let (w, h) = (
            width as bindings::types::GLsizei,
            height as bindings::types::GLsizei,
        );
        let mut framebuffer = Framebuffer {
            gl,
            framebuffer: 0,
            renderbuffers: [0; 2],
        };
        // SAFETY: a context is current on this thread; each Gen call writes as many names as
        // it is given room for. From here on `framebuffer` owns the names (zero names are
        // ignored by the Delete calls in Drop).
        unsafe {
            gl.GenFramebuffers(1, &mut framebuffer.framebuffer);
            gl.GenRenderbuffers(2, framebuffer.renderbuffers.as_mut_ptr());
        }
        let [color, depth] = framebuffer.renderbuffers;
        // SAFETY: a context is current on this thread; the names were just generated, and the
        // sizes are within GL_MAX_RENDERBUFFER_SIZE.
        let status = unsafe {
            gl.BindRenderbuffer(bindings::RENDERBUFFER, color);
            gl.RenderbufferStorage(bindings::RENDERBUFFER, bindings::RGBA8, w, h);
            gl.BindRenderbuffer(bindings::RENDERBUFFER, depth);
            gl.RenderbufferStorage(bindings::RENDERBUFFER, bindings::DEPTH24_STENCIL8, w, h);
            gl.BindRenderbuffer(bindings::RENDERBUFFER, 0);
            gl.BindFramebuffer(bindings::FRAMEBUFFER, framebuffer.framebuffer);
            gl.FramebufferRenderbuffer(
                bindings::FRAMEBUFFER,
                bindings::COLOR_ATTACHMENT0,
                bindings::RENDERBUFFER,
                color,
            );
            gl.FramebufferRenderbuffer(
                bindings::FRAMEBUFFER,
                bindings::DEPTH_STENCIL_ATTACHMENT,
                bindings::RENDERBUFFER,
                depth,
            );
            gl.DrawBuffer(bindings::COLOR_ATTACHMENT0);
            gl.ReadBuffer(bindings::COLOR_ATTACHMENT0);
            gl.CheckFramebufferStatus(bindings::FRAMEBUFFER)
        };
        // An allocation the driver refused shows as GL_OUT_OF_MEMORY here.
        let codes = drain_errors(gl);
        if !codes.is_empty() {
            return Err(GlError::Gl {
                codes,
                when: format!("while making a {width}x{height} framebuffer object"),
            });
        }
        if status != bindings::FRAMEBUFFER_COMPLETE {
            return Err(GlError::IncompleteFramebuffer { status });
        }
        Ok(framebuffer)
    }
}

impl Drop for Framebuffer<'_> {
    fn drop(&mut self) {
        // SAFETY: the context that made the names is current (the framebuffer never outlives
        // its session); deleting zero or deleted names is a no-op in GL.
        unsafe {
            self.gl.BindFramebuffer(bindings::FRAMEBUFFER, 0);
            self.gl.DeleteFramebuffers(1, &self.framebuffer);
            self.gl.DeleteRenderbuffers(2, self.renderbuffers.as_ptr());
        }
    }
}

/// Every pending GL error flag (at most 16: a broken driver could report one forever).
pub(super) fn drain_errors(gl: &Gl) -> Vec<u32> {
    let mut codes = Vec::new();
    while codes.len() < 16 {
        // SAFETY: a context is current on this thread.
        let code = unsafe { gl.GetError() };
        if code == bindings::NO_ERROR {
            break;
        }
        codes.push(code);
    }
    codes
}

/// The GL errors of one draw's calls since the last check, as a [`DrawError`] naming `when`.
pub(super) fn check_draw(gl: &Gl, when: &'static str) -> Result<(), DrawError> {
    let codes = drain_errors(gl);
    if codes.is_empty() {
        Ok(())
    } else {
        Err(DrawError::Gl { codes, when })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn device(uuid: Option<[u8; 16]>, name: Option<&str>) -> Candidate {
        Candidate {
            platform: PLATFORM_DEVICE_EXT,
            device: std::ptr::null_mut(),
            description: "a device".into(),
            software: false,
            uuid,
            name: name.map(String::from),
        }
    }

    fn matches(candidate: &Candidate, options: &GlOptions) -> bool {
        matches!(pre_match(candidate, options), Match::Yes)
    }

    #[test]
    fn extension_names_match_whole_words_only() {
        let list = "EGL_EXT_device_base EGL_EXT_platform_device  EGL_MESA_platform_surfaceless";
        assert!(has_extension(list, "EGL_EXT_platform_device"));
        assert!(has_extension(list, "EGL_MESA_platform_surfaceless"));
        assert!(!has_extension(list, "EGL_EXT_platform"));
        assert!(!has_extension(list, "EGL_EXT_device_base_more"));
        assert!(!has_extension("", "EGL_EXT_device_base"));
    }

    #[test]
    fn a_reported_uuid_decides_before_the_name() {
        let uuid = [7u8; 16];
        let by_uuid = GlOptions {
            vulkan_uuid: Some(uuid),
            vulkan_name: Some("NVIDIA H200".into()),
            ..GlOptions::default()
        };
        // Same UUID: a match whatever the name says.
        assert!(matches(&device(Some(uuid), Some("something else")), &by_uuid));
        // Another UUID: no match even with the same name.
        assert!(!matches(&device(Some([8; 16]), Some("NVIDIA H200")), &by_uuid));
        // No UUID: the name decides (here EGL_RENDERER_EXT; GL_RENDERER once a context exists).
        assert!(matches(&device(None, Some("NVIDIA H200/PCIe/SSE2")), &by_uuid));
        assert!(!matches(
            &device(None, Some("llvmpipe (LLVM 15.0.6, 256 bits)")),
            &by_uuid
        ));
        assert!(matches(&device(None, None), &by_uuid));
    }

    #[test]
    fn names_match_by_containment_ignoring_case() {
        let by_name = GlOptions {
            vulkan_name: Some("LLVMpipe (LLVM 15.0.6, 256 bits)".into()),
            ..GlOptions::default()
        };
        assert!(matches(
            &device(None, Some("llvmpipe (LLVM 15.0.6, 256 bits)")),
            &by_name
        ));
        assert!(!matches(
            &device(None, Some("llvmpipe (LLVM 16.0.0, 128 bits)")),
            &by_name
        ));
        // Without a request, every device matches.
        assert!(matches(
            &device(Some([1; 16]), Some("anything")),
            &GlOptions::default()
        ));
        assert_eq!(wanted(&GlOptions::default()), None);
        assert_eq!(
            wanted(&GlOptions {
                vulkan_uuid: Some([0xab; 16]),
                ..GlOptions::default()
            })
            .as_deref(),
            Some("the Vulkan device with UUID abababababababababababababababab")
        );
    }
}
