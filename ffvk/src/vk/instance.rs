//! The Vulkan instance, with an optional validation layer whose messages go to a sink owned
//! by this instance alone.

use std::ffi::{c_void, CStr};
use std::sync::{Arc, Mutex};

use ash::{ext, vk};

use crate::error::{vk_error, Error, Result};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// Whether to load `VK_LAYER_KHRONOS_validation`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Validation {
    /// No validation layer.
    #[default]
    Off,
    /// Use it when installed, else run without it ([`crate::vk::DeviceInfo::validation`] tells
    /// which; [`validation_layer_installed`] asks beforehand).
    IfPresent,
    /// Fail with [`Error::NoValidationLayer`] when it is not installed (tests).
    Required,
}

/// Validation messages of one instance. Errors fail the frame that caused them
/// ([`crate::Renderer::render`]); warnings are kept for inspection.
#[derive(Debug, Clone, Default)]
pub struct ValidationSink {
    inner: Arc<Mutex<SinkMessages>>,
}

#[derive(Debug, Default)]
struct SinkMessages {
    errors: Vec<String>,
    warnings: Vec<String>,
}

impl ValidationSink {
    /// Removes and returns the errors reported so far.
    pub fn take_errors(&self) -> Vec<String> {
        self.inner
            .lock()
            .map(|mut m| std::mem::take(&mut m.errors))
            .unwrap_or_default()
    }

    /// Removes and returns the warnings reported so far.
    pub fn take_warnings(&self) -> Vec<String> {
        self.inner
            .lock()
            .map(|mut m| std::mem::take(&mut m.warnings))
            .unwrap_or_default()
    }

    fn push(&self, error: bool, message: String) {
        // A poisoned lock loses the message rather than panicking inside a Vulkan callback.
        if let Ok(mut m) = self.inner.lock() {
            if error {
                m.errors.push(message);
            } else {
                m.warnings.push(message);
            }
        }
    }
}

/// A Vulkan instance and, when validation is on, its debug messenger.
pub struct Instance {
    pub(crate) entry: ash::Entry,
    pub(crate) raw: ash::Instance,
    messenger: Option<(ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    /// Owned here so the pointer handed to the messenger stays valid until it is destroyed.
    sink: Box<ValidationSink>,
    validation_enabled: bool,
}

/// Whether `VK_LAYER_KHRONOS_validation` is installed (asks the Vulkan loader).
pub fn validation_layer_installed() -> Result<bool> {
    // SAFETY: loading the system's Vulkan loader runs its initialisers; nothing else is
    // loaded alongside.
    let entry = unsafe { ash::Entry::load() }.map_err(|e| Error::NoLoader(e.to_string()))?;
    // SAFETY: entry is a loaded loader; a null layer name asks for instance layers.
    let layers = unsafe { entry.enumerate_instance_layer_properties() }
        .map_err(vk_error("vkEnumerateInstanceLayerProperties"))?;
    Ok(layers
        .iter()
        .any(|l| l.layer_name_as_c_str().is_ok_and(|name| name == VALIDATION_LAYER)))
}

impl Instance {
    /// Loads the Vulkan loader and creates a Vulkan 1.3 instance, with the validation layer
    /// as `validation` asks. Fails with [`Error::NoLoader`] without `libvulkan.so.1`, and
    /// with [`Error::NoValidationLayer`] when the layer is required but not installed;
    /// [`Validation::IfPresent`] then goes on without it, silently (the caller may ask
    /// [`validation_layer_installed`] first and warn).
    pub fn new(validation: Validation) -> Result<Arc<Self>> {
        // SAFETY: loading the system's Vulkan loader runs its initialisers; that is the
        // documented way to start with Vulkan and nothing else is loaded alongside.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| Error::NoLoader(e.to_string()))?;

        // SAFETY: entry is a loaded loader; a null layer name asks for instance layers.
        let layers = unsafe { entry.enumerate_instance_layer_properties() }
            .map_err(vk_error("vkEnumerateInstanceLayerProperties"))?;
        let has_layer = layers
            .iter()
            .any(|l| l.layer_name_as_c_str().is_ok_and(|name| name == VALIDATION_LAYER));
        let validation_enabled = match (validation, has_layer) {
            (Validation::Off, _) => false,
            (_, true) => true,
            (Validation::IfPresent, false) => false,
            (Validation::Required, false) => return Err(Error::NoValidationLayer),
        };

        let app = vk::ApplicationInfo::default()
            .application_name(c"ffvk")
            .engine_name(c"ffvk")
            .api_version(vk::API_VERSION_1_3);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let extension_names = [ext::debug_utils::NAME.as_ptr()];
        let mut info = vk::InstanceCreateInfo::default().application_info(&app);
        if validation_enabled {
            info = info
                .enabled_layer_names(&layer_names)
                .enabled_extension_names(&extension_names);
        }
        // SAFETY: info and the strings it points to live until the call returns.
        let raw = unsafe { entry.create_instance(&info, None) }.map_err(vk_error("vkCreateInstance"))?;

        let sink = Box::new(ValidationSink::default());
        let mut instance = Instance {
            entry,
            raw,
            messenger: None,
            sink,
            validation_enabled,
        };
        if validation_enabled {
            let loader = ext::debug_utils::Instance::new(&instance.entry, &instance.raw);
            let info = vk::DebugUtilsMessengerCreateInfoEXT::default()
                .message_severity(
                    vk::DebugUtilsMessageSeverityFlagsEXT::ERROR
                        | vk::DebugUtilsMessageSeverityFlagsEXT::WARNING,
                )
                .message_type(
                    vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                        | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
                )
                .pfn_user_callback(Some(debug_callback))
                .user_data(&*instance.sink as *const ValidationSink as *mut c_void);
            // SAFETY: the user-data pointer targets the boxed sink, which the instance owns
            // and drops only after destroying the messenger (see Drop).
            let messenger = unsafe { loader.create_debug_utils_messenger(&info, None) }
                .map_err(vk_error("vkCreateDebugUtilsMessengerEXT"))?;
            instance.messenger = Some((loader, messenger));
        }
        Ok(Arc::new(instance))
    }

    /// Whether the validation layer is active on this instance.
    pub fn validation_enabled(&self) -> bool {
        self.validation_enabled
    }

    /// This instance's validation messages.
    pub fn validation_sink(&self) -> ValidationSink {
        (*self.sink).clone()
    }
}

impl Drop for Instance {
    fn drop(&mut self) {
        // SAFETY: every child (devices hold an Arc<Instance>) is gone by now; the messenger
        // is destroyed before the instance and before the sink it points to.
        unsafe {
            if let Some((loader, messenger)) = self.messenger.take() {
                loader.destroy_debug_utils_messenger(messenger, None);
            }
            self.raw.destroy_instance(None);
        }
    }
}

/// Records a validation message in the sink of the instance that reported it.
/// It must not panic: unwinding across the C boundary would abort.
unsafe extern "system" fn debug_callback(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user_data: *mut c_void,
) -> vk::Bool32 {
    if data.is_null() || user_data.is_null() {
        return vk::FALSE;
    }
    // SAFETY: user_data is the instance's boxed sink (set at messenger creation, alive
    // until after the messenger is destroyed); data is valid for this call per the spec.
    let (sink, data) = unsafe { (&*(user_data as *const ValidationSink), &*data) };
    let message = if data.p_message.is_null() {
        String::from("(no message)")
    } else {
        // SAFETY: p_message is a NUL-terminated string valid for this call.
        unsafe { CStr::from_ptr(data.p_message) }
            .to_string_lossy()
            .into_owned()
    };
    sink.push(
        severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::ERROR),
        message,
    );
    vk::FALSE
}
