//! The floor's own Vulkan instance and device: a plain program's, with what its data paths
//! need (dynamic rendering, `shaderDrawParameters` for `gl_DrawID`, `VK_EXT_multi_draw` where
//! the device has it), wrapped in an ffvk [`Device`] so that ffvk's buffers, images and
//! owned objects (`ffvk::vk`) can live on it and free themselves in `Drop`.

use std::ffi::{c_void, CStr};
use std::sync::{Arc, Mutex};

use ash::{ext, vk};
use ffvk::vk::{Device, EnabledFeatures, Validation};

use crate::{Error, Result};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// A failed Vulkan call as ffvk reports one.
pub(super) fn failed(call: &'static str) -> impl Fn(vk::Result) -> Error {
    move |result| Error::Core(ffvk::Error::Vulkan { call, result })
}

/// The validation layer's messages (errors and warnings alike), collected by the messenger.
type Messages = Mutex<Vec<String>>;

/// The debug messenger's callback: keeps the message.
unsafe extern "system" fn collect(
    _severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes valid callback data for the duration of the call, and `user`
    // is the `Messages` box the context owns until after the messenger is destroyed.
    unsafe {
        if let (Some(data), Some(messages)) = (data.as_ref(), (user as *const Messages).as_ref()) {
            let text = data
                .message_as_c_str()
                .map_or_else(|| "(no message)".into(), |m| m.to_string_lossy().into_owned());
            if let Ok(mut list) = messages.lock() {
                list.push(text);
            }
        }
    }
    vk::FALSE
}

/// An instance, its device and queue; destroyed in `Drop` after ffvk's wrapper of the device.
pub(super) struct Context {
    entry: ash::Entry,
    instance: ash::Instance,
    messenger: Option<(ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    /// Where the messenger writes; freed after the messenger is destroyed.
    messages: Box<Messages>,
    /// `None` until the device exists (and while it is being destroyed).
    device: Option<ash::Device>,
    /// ffvk's wrapper of `device`, which ffvk's objects hold; the last `Arc` is dropped here
    /// before `device` is destroyed.
    ffvk: Option<Arc<Device>>,
    pub(super) queue: vk::Queue,
    pub(super) queue_family: u32,
    /// `VK_EXT_multi_draw`'s entry points and `maxMultiDrawCount`, where the device has it
    /// (and `shaderDrawParameters`, which `gl_DrawID` needs).
    pub(super) multi_draw: Option<(ext::multi_draw::Device, u32)>,
    pub(super) limits: vk::PhysicalDeviceLimits,
}

impl Context {
    /// Opens the device whose name contains `requested` (lavapipe, "llvmpipe", by default),
    /// with the validation layer as `validation` asks.
    pub(super) fn new(requested: Option<&str>, validation: Validation) -> Result<Self> {
        // SAFETY: loading the system's Vulkan loader runs its initialisers; nothing else is
        // loaded alongside.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| ffvk::Error::NoLoader(e.to_string()))?;
        // SAFETY: entry is a loaded loader; no layer name asks for the instance's layers.
        let layers = unsafe { entry.enumerate_instance_layer_properties() }
            .map_err(failed("vkEnumerateInstanceLayerProperties"))?;
        let has_layer = layers
            .iter()
            .any(|l| l.layer_name_as_c_str().is_ok_and(|n| n == VALIDATION_LAYER));
        let validate = match (validation, has_layer) {
            (Validation::Off, _) | (Validation::IfPresent, false) => false,
            (Validation::Required, false) => return Err(ffvk::Error::NoValidationLayer.into()),
            _ => true,
        };
        let app = vk::ApplicationInfo::default()
            .application_name(c"ffvk bench floor")
            .api_version(vk::API_VERSION_1_3);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let extension_names = [ext::debug_utils::NAME.as_ptr()];
        let mut info = vk::InstanceCreateInfo::default().application_info(&app);
        if validate {
            info = info
                .enabled_layer_names(&layer_names)
                .enabled_extension_names(&extension_names);
        }
        // SAFETY: info and the strings it points to live until the call returns.
        let instance = unsafe { entry.create_instance(&info, None) }.map_err(failed("vkCreateInstance"))?;
        let mut context = Context {
            entry,
            instance,
            messenger: None,
            messages: Box::default(),
            device: None,
            ffvk: None,
            queue: vk::Queue::null(),
            queue_family: 0,
            multi_draw: None,
            limits: vk::PhysicalDeviceLimits::default(),
        };
        if validate {
            context.add_messenger()?;
        }
        context.open_device(requested)?;
        Ok(context)
    }

    fn add_messenger(&mut self) -> Result<()> {
        let loader = ext::debug_utils::Instance::new(&self.entry, &self.instance);
        let info = vk::DebugUtilsMessengerCreateInfoEXT::default()
            .message_severity(
                vk::DebugUtilsMessageSeverityFlagsEXT::ERROR | vk::DebugUtilsMessageSeverityFlagsEXT::WARNING,
            )
            .message_type(
                vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                    | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                    | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
            )
            .pfn_user_callback(Some(collect))
            .user_data(&*self.messages as *const Messages as *mut c_void);
        // SAFETY: the user data is the boxed message list, which lives until Drop has
        // destroyed the messenger.
        let messenger = unsafe { loader.create_debug_utils_messenger(&info, None) }
            .map_err(failed("vkCreateDebugUtilsMessengerEXT"))?;
        self.messenger = Some((loader, messenger));
        Ok(())
    }

    fn open_device(&mut self, requested: Option<&str>) -> Result<()> {
        let vki = &self.instance;
        // SAFETY: the instance is alive.
        let physicals =
            unsafe { vki.enumerate_physical_devices() }.map_err(failed("vkEnumeratePhysicalDevices"))?;
        let name = |p: vk::PhysicalDevice| {
            // SAFETY: p comes from this instance's enumeration.
            let props = unsafe { vki.get_physical_device_properties(p) };
            props
                .device_name_as_c_str()
                .map(|n| n.to_string_lossy().to_lowercase())
                .unwrap_or_default()
        };
        let wanted = requested.unwrap_or("llvmpipe").to_lowercase();
        let physical = physicals
            .iter()
            .copied()
            .find(|&p| name(p).contains(&wanted))
            .or_else(|| physicals.first().copied().filter(|_| requested.is_none()))
            .ok_or_else(|| Error::Bench(format!("the floor found no Vulkan device named {wanted:?}")))?;
        // SAFETY: physical comes from this instance.
        let (props, families, extensions) = unsafe {
            (
                vki.get_physical_device_properties(physical),
                vki.get_physical_device_queue_family_properties(physical),
                vki.enumerate_device_extension_properties(physical)
                    .map_err(failed("vkEnumerateDeviceExtensionProperties"))?,
            )
        };
        if props.api_version < vk::API_VERSION_1_3 {
            return Err(ffvk::Error::MissingFeature("Vulkan 1.3".into()).into());
        }
        self.limits = props.limits;
        self.queue_family = families
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .ok_or_else(|| ffvk::Error::MissingFeature("a graphics queue".into()))?
            as u32;

        let mut v11 = vk::PhysicalDeviceVulkan11Features::default();
        let mut v13 = vk::PhysicalDeviceVulkan13Features::default();
        let mut multi = vk::PhysicalDeviceMultiDrawFeaturesEXT::default();
        let mut multi_props = vk::PhysicalDeviceMultiDrawPropertiesEXT::default();
        {
            let mut features = vk::PhysicalDeviceFeatures2::default()
                .push_next(&mut v11)
                .push_next(&mut v13)
                .push_next(&mut multi);
            let mut props2 = vk::PhysicalDeviceProperties2::default().push_next(&mut multi_props);
            // SAFETY: the chained structs live until the calls return; physical is valid.
            unsafe {
                vki.get_physical_device_features2(physical, &mut features);
                vki.get_physical_device_properties2(physical, &mut props2);
            }
        }
        if v13.dynamic_rendering != vk::TRUE {
            return Err(ffvk::Error::MissingFeature("dynamicRendering".into()).into());
        }
        let has_multi_draw = extensions.iter().any(|e| {
            e.extension_name_as_c_str()
                .is_ok_and(|n| n == ext::multi_draw::NAME)
        });
        let multi_draw =
            has_multi_draw && multi.multi_draw == vk::TRUE && v11.shader_draw_parameters == vk::TRUE;

        let priorities = [1.0f32];
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(self.queue_family)
            .queue_priorities(&priorities)];
        let extension_names = [ext::multi_draw::NAME.as_ptr()];
        let mut enable_v11 = vk::PhysicalDeviceVulkan11Features::default().shader_draw_parameters(multi_draw);
        let mut enable_v13 = vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(true);
        let mut enable_multi = vk::PhysicalDeviceMultiDrawFeaturesEXT::default().multi_draw(true);
        let mut create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .push_next(&mut enable_v11)
            .push_next(&mut enable_v13);
        if multi_draw {
            create = create
                .enabled_extension_names(&extension_names)
                .push_next(&mut enable_multi);
        }
        // SAFETY: the create info and what it points to live until the call returns.
        let device =
            unsafe { vki.create_device(physical, &create, None) }.map_err(failed("vkCreateDevice"))?;
        // SAFETY: family and index 0 were requested above.
        self.queue = unsafe { device.get_device_queue(self.queue_family, 0) };
        self.multi_draw = multi_draw.then(|| {
            (
                ext::multi_draw::Device::new(vki, &device),
                multi_props.max_multi_draw_count,
            )
        });
        self.device = Some(device.clone());
        let enabled = EnabledFeatures::default().with_dynamic_rendering(true);
        // SAFETY: `device` was created above from `physical` of this instance with dynamic
        // rendering on, and is destroyed (in Drop) only after this wrapper's last Arc.
        self.ffvk = Some(unsafe { Device::from_caller(vki, physical, device, enabled) }?);
        Ok(())
    }

    /// The device, for recording and creating what ffvk has no wrapper for.
    pub(super) fn device(&self) -> Result<&ash::Device> {
        self.device
            .as_ref()
            .ok_or_else(|| Error::Bench("the floor's device is gone".into()))
    }

    /// ffvk's wrapper of the device, which ffvk's buffers, images and objects take.
    pub(super) fn ffvk(&self) -> Result<&Arc<Device>> {
        self.ffvk
            .as_ref()
            .ok_or_else(|| Error::Bench("the floor's device is gone".into()))
    }

    /// Fails with the validation layer's messages since the last call, if there were any.
    pub(super) fn check_validation(&self) -> Result<()> {
        let messages = match self.messages.lock() {
            Ok(mut list) => std::mem::take(&mut *list),
            Err(_) => vec!["the validation message list was poisoned".into()],
        };
        if messages.is_empty() {
            Ok(())
        } else {
            Err(ffvk::Error::Validation(messages).into())
        }
    }
}

impl Context {
    /// Destroys the device (after the last ffvk object on it) and fails with the validation
    /// layer's messages up to then.
    pub(super) fn close(mut self) -> Result<()> {
        self.destroy_device();
        self.check_validation()
    }

    /// Waits for the device and destroys it; returns whether it is gone (false: ffvk objects
    /// still hold it, and it is leaked rather than destroyed under them).
    fn destroy_device(&mut self) -> bool {
        let Some(device) = self.device.take() else {
            return true;
        };
        // SAFETY: the device is alive; nothing else submits to its queue.
        let _ = unsafe { device.device_wait_idle() };
        // Every ffvk object on the device holds an Arc of the wrapper: only when this is the
        // last one are they all gone and its memory returned (dropping it).
        let childless = match self.ffvk.take().map(Arc::into_inner) {
            Some(Some(wrapper)) => {
                drop(wrapper);
                true
            }
            Some(None) => false,
            // Made but never wrapped (from_caller failed): no child exists.
            None => true,
        };
        if childless {
            // SAFETY: idle, and no child is left.
            unsafe { device.destroy_device(None) };
        }
        childless
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        if !self.destroy_device() {
            // The device is leaked, and so its instance; the messenger stays registered on
            // it, and so does its list.
            Box::leak(std::mem::take(&mut self.messages));
            return;
        }
        if let Some((loader, messenger)) = self.messenger.take() {
            // SAFETY: created on this instance, destroyed once; the message box outlives it.
            unsafe { loader.destroy_debug_utils_messenger(messenger, None) };
        }
        // SAFETY: the instance's children (the device, the messenger) are destroyed above.
        unsafe { self.instance.destroy_instance(None) };
    }
}
