/* teapot.c: ffvk's C API inside a plain C Vulkan program.
 *
 * The C twin of ffvk/examples/embed.rs, for a fixed-function emulation layer to copy from.
 * Every Vulkan object is this program's own: the instance, the device and its queue, the
 * command pool and buffer, the vertex, index and readback buffers, the color and depth
 * images and the fence. ffvk gets the device through FfvkRendererCreateInfo and records GL's
 * lighting into our command buffer, inside our own vkCmdBeginRendering; it never submits or
 * waits. GL's state goes through an FfvkContext with GL's entry points, as a layer would hand
 * on the application's glEnable/glLightfv/glMaterialfv calls.
 *
 * The teapot is drawn in ffvk's three lighting modes and written as binary PPM files:
 *
 *     make -C ffvk-c/examples run          # into ffvk-c/examples/out/
 *     ./teapot DIR                         # teapot_vertex.ppm, teapot_fragment.ppm, teapot_flat.ppm
 *
 * Environment: FFVK_DEVICE picks the device by a substring of its name (lavapipe, "llvmpipe",
 * by default); FFVK_VALIDATION=1 turns on the Khronos validation layer, and any warning or
 * error it reports fails the run. The test suite (tests/suite/c_api_example.rs) requires
 * these images to be byte for byte the Rust example's. */

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <vulkan/vulkan.h>

#include "ffvk.h"

#define SIZE 256u
static const float CLEAR[4] = {0.08f, 0.08f, 0.1f, 1.0f};
#define COLOR_FORMAT VK_FORMAT_R8G8B8A8_UNORM
#define DEPTH_FORMAT VK_FORMAT_D32_SFLOAT

/* ------------------------------------------------------------------------------------------
 * Failing loudly. An example exits on the first failure; a layer would turn these into GL
 * errors or its own reporting instead. */

static void die(const char *format, ...) {
    va_list args;
    va_start(args, format);
    fputs("teapot: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}

#define VK_CHECK(call)                                                                       \
    do {                                                                                     \
        VkResult vk_check_result_ = (call);                                                  \
        if (vk_check_result_ != VK_SUCCESS)                                                  \
            die("%s:%d: %s: VkResult %d", __FILE__, __LINE__, #call, (int)vk_check_result_); \
    } while (0)

/* Every FfvkResult-returning call comes with a message saying what was wrong and what was
 * expected: print it, the code alone rarely says enough. */
#define FFVK_CHECK(call)                                                                     \
    do {                                                                                     \
        FfvkResult ffvk_check_result_ = (call);                                              \
        if (ffvk_check_result_ != FFVK_SUCCESS)                                              \
            die("%s:%d: %s: FfvkResult %d: %s", __FILE__, __LINE__, #call,                   \
                (int)ffvk_check_result_, ffvkResultMessage());                               \
    } while (0)

/* The context's entry points return nothing, as GL's do: a refused call sets GL's error flag,
 * read (and cleared) by ffvkGetError, with its message in ffvkResultMessage. */
static void check_gl(FfvkContext *ctx, const char *what) {
    uint32_t error = ffvkGetError(ctx);
    if (error != GL_NO_ERROR)
        die("%s: GL error 0x%04X: %s", what, (unsigned)error, ffvkResultMessage());
}

/* ------------------------------------------------------------------------------------------
 * The camera, as glam 0.29 computes embed.rs's view() and projection(). A layer has no such
 * code: its matrices are the application's (glLoadMatrixf, glFrustum, its matrix stacks).
 *
 * Byte-identical images need bit-identical matrices, so these follow glam's Mat4::look_at_rh
 * and Mat4::perspective_rh_gl operation for operation in float: no double intermediates, no
 * reassociation, normalize as v * (1 / sqrt(dot)), and a * b + c as two roundings as Rust
 * does (the Makefile's -ffp-contract=off: no fused multiply-adds). Matrices are column-major,
 * as glLoadMatrixf and ffvkLoadModelview take them. */

typedef struct { float x, y, z; } Vec3;

static Vec3 vec3(float x, float y, float z) {
    Vec3 v = {x, y, z};
    return v;
}
static Vec3 sub(Vec3 a, Vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
static float dot(Vec3 a, Vec3 b) { return (a.x * b.x) + (a.y * b.y) + (a.z * b.z); }
static Vec3 cross(Vec3 a, Vec3 b) {
    return vec3(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}
static Vec3 normalize(Vec3 v) {
    float recip = 1.0f / sqrtf(dot(v, v));
    return vec3(v.x * recip, v.y * recip, v.z * recip);
}

/* gluLookAt's matrix: eye space from world space. */
static void look_at_rh(Vec3 eye, Vec3 center, Vec3 up, float m[16]) {
    Vec3 f = normalize(sub(center, eye));
    Vec3 s = normalize(cross(f, up));
    Vec3 u = cross(s, f);
    const float cols[16] = {
        s.x, u.x, -f.x, 0.0f,
        s.y, u.y, -f.y, 0.0f,
        s.z, u.z, -f.z, 0.0f,
        -dot(eye, s), -dot(eye, u), dot(eye, f), 1.0f,
    };
    memcpy(m, cols, sizeof cols);
}

/* gluPerspective's matrix: GL's clip space, z in [-w, w] (ffvk maps it to Vulkan's). */
static void perspective_rh_gl(float fov_y_radians, float aspect, float z_near, float z_far,
                              float m[16]) {
    float inv_length = 1.0f / (z_near - z_far);
    float f = 1.0f / tanf(0.5f * fov_y_radians); /* the C library's, as Rust's f32::tan */
    float a = f / aspect;
    float b = (z_near + z_far) * inv_length;
    float c = (2.0f * z_near * z_far) * inv_length;
    const float cols[16] = {
        a, 0.0f, 0.0f, 0.0f,
        0.0f, f, 0.0f, 0.0f,
        0.0f, 0.0f, b, -1.0f,
        0.0f, 0.0f, c, 0.0f,
    };
    memcpy(m, cols, sizeof cols);
}

static void view(float m[16]) {
    look_at_rh(vec3(0.0f, 1.2f, 3.0f), vec3(0.0f, -0.05f, 0.0f), vec3(0.0f, 1.0f, 0.0f), m);
}

static void projection(float m[16]) {
    /* Rust's f32::to_radians multiplies by PI / 180 rounded to float once; dividing by 180
     * after the multiplication can round differently. */
    const float radians_per_degree = 3.14159265358979323846f / 180.0f;
    perspective_rh_gl(40.0f * radians_per_degree, 1.0f, 0.5f, 10.0f, m);
}

/* ------------------------------------------------------------------------------------------
 * GL's state for the teapot, set through GL's entry points as the application would: a
 * brass-like material, two lights (a white directional key light and a warm positional fill),
 * two-sided lighting. embed.rs's gl_state() makes the same calls on ffvk's GlState. */

typedef struct {
    const char *name;     /* the output file's: teapot_<name>.ppm */
    uint32_t shade_model; /* glShadeModel */
    uint8_t per_fragment; /* ffvk's extension: GL_SMOOTH lit per fragment */
} Mode;

static const Mode MODES[] = {
    {"vertex", GL_SMOOTH, 0},
    {"fragment", GL_SMOOTH, 1},
    {"flat", GL_FLAT, 0},
};

static FfvkContext *teapot_state(const Mode *mode) {
    FfvkContext *ctx = ffvkCreateContext();
    if (!ctx)
        die("ffvkCreateContext: %s", ffvkResultMessage());

    ffvkEnable(ctx, GL_LIGHTING);
    ffvkEnable(ctx, GL_LIGHT0);
    ffvkEnable(ctx, GL_LIGHT1);
    ffvkShadeModel(ctx, mode->shade_model);
    ffvkPerFragmentLighting(ctx, mode->per_fragment);

    const float ambient[4] = {0.33f, 0.22f, 0.03f, 1.0f};
    const float diffuse[4] = {0.78f, 0.57f, 0.11f, 1.0f};
    const float specular[4] = {0.99f, 0.94f, 0.81f, 1.0f};
    ffvkMaterialfv(ctx, GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    ffvkMaterialfv(ctx, GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    ffvkMaterialfv(ctx, GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    ffvkMaterialf(ctx, GL_FRONT_AND_BACK, GL_SHININESS, 27.9f);
    ffvkLightModeli(ctx, GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);

    /* As in GL, a light's position is transformed by the modelview current when it is given:
     * load the camera first, so these are world-space positions. */
    float modelview[16];
    view(modelview);
    ffvkLoadModelview(ctx, modelview);
    const float key_position[4] = {1.0f, 1.5f, 1.2f, 0.0f}; /* w = 0: directional */
    const float fill_position[4] = {-2.0f, 0.5f, 1.0f, 1.0f};
    const float fill_diffuse[4] = {0.6f, 0.4f, 0.3f, 1.0f};
    ffvkLightfv(ctx, GL_LIGHT0, GL_POSITION, key_position);
    ffvkLightfv(ctx, GL_LIGHT1, GL_POSITION, fill_position);
    ffvkLightfv(ctx, GL_LIGHT1, GL_DIFFUSE, fill_diffuse);
    ffvkLightf(ctx, GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.3f);

    /* The projection is not lighting state, but draws take it from the context too. */
    float proj[16];
    projection(proj);
    ffvkLoadProjection(ctx, proj);

    /* GL keeps only the first error; checking once after the batch finds any of them. */
    check_gl(ctx, mode->name);
    return ctx;
}

/* ------------------------------------------------------------------------------------------
 * The application's own Vulkan objects. */

typedef struct {
    VkBuffer buffer;
    VkDeviceMemory memory;
} Buffer;

typedef struct {
    VkImage image;
    VkImageView view;
    VkDeviceMemory memory;
} Image;

typedef struct {
    VkInstance instance;
    VkDebugUtilsMessengerEXT messenger; /* VK_NULL_HANDLE without validation */
    VkPhysicalDevice physical;
    VkDevice device;
    uint32_t family;
    VkQueue queue;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    VkFence fence;
    uint32_t ffvk_features; /* FFVK_FEATURE_* bits the device was created with */

    /* Positions (binding 0); normals with 8-bit colors (binding 1). */
    Buffer positions, normal_colors, indices, readback;
    uint32_t index_count;
    Image color, depth;
} App;

/* Validation messages of warning or error severity: each one fails the run. */
static unsigned validation_messages = 0;

static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
    const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    (void)type;
    (void)user;
    if (severity & (VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)) {
        validation_messages++;
        fprintf(stderr, "teapot: validation: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

static void ascii_lower(char *s) {
    for (; *s; s++)
        if (*s >= 'A' && *s <= 'Z')
            *s = (char)(*s - 'A' + 'a');
}

static void create_instance(App *app, int validation) {
    /* ffvk needs Vulkan 1.3 (dynamic rendering), and says so at ffvkCreateRenderer. */
    VkApplicationInfo application = {
        .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
        .pApplicationName = "ffvk teapot.c",
        .apiVersion = VK_API_VERSION_1_3,
    };
    const char *layers[] = {"VK_LAYER_KHRONOS_validation"};
    const char *extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    VkInstanceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        .pApplicationInfo = &application,
    };
    if (validation) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = layers;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = extensions;
    }
    VK_CHECK(vkCreateInstance(&info, NULL, &app->instance));
    if (!validation)
        return;
    VkDebugUtilsMessengerCreateInfoEXT messenger = {
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
        .pfnUserCallback = on_message,
    };
    /* An extension's functions are not exported by the loader: ask the instance. */
    PFN_vkCreateDebugUtilsMessengerEXT create = (PFN_vkCreateDebugUtilsMessengerEXT)
        vkGetInstanceProcAddr(app->instance, "vkCreateDebugUtilsMessengerEXT");
    if (!create)
        die("vkCreateDebugUtilsMessengerEXT is missing");
    VK_CHECK(create(app->instance, &messenger, NULL, &app->messenger));
}

static void pick_device(App *app, const char *wanted_name) {
    char wanted[VK_MAX_PHYSICAL_DEVICE_NAME_SIZE];
    snprintf(wanted, sizeof wanted, "%s", wanted_name);
    ascii_lower(wanted);

    VkPhysicalDevice physicals[16];
    uint32_t count = 16;
    VkResult listed = vkEnumeratePhysicalDevices(app->instance, &count, physicals);
    if (listed != VK_SUCCESS && listed != VK_INCOMPLETE)
        die("vkEnumeratePhysicalDevices: VkResult %d", (int)listed);
    for (uint32_t i = 0; i < count && !app->physical; i++) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(physicals[i], &props);
        ascii_lower(props.deviceName);
        if (strstr(props.deviceName, wanted))
            app->physical = physicals[i];
    }
    if (!app->physical)
        die("no Vulkan device named like \"%s\"", wanted);

    VkQueueFamilyProperties families[16];
    uint32_t family_count = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(app->physical, &family_count, families);
    app->family = UINT32_MAX;
    for (uint32_t i = 0; i < family_count && app->family == UINT32_MAX; i++)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)
            app->family = i;
    if (app->family == UINT32_MAX)
        die("no graphics queue");
}

static void create_device(App *app) {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
        .queueFamilyIndex = app->family,
        .queueCount = 1,
        .pQueuePriorities = &priority,
    };
    /* This program's own feature: synchronization2 (vkCmdPipelineBarrier2). ffvk adds what it
     * uses to the same chain: dynamicRendering (required) in the Vulkan 1.3 struct,
     * provokingVertexLast (GL's rule for GL_FLAT: the last vertex) in the provoking-vertex
     * struct, GL's aliased and stippled lines (bresenhamLines, stippledBresenhamLines) in the
     * line-rasterization struct, GL 2.1's cube map filtering, each face on its own
     * (nonSeamlessCubeMap) in the non-seamless struct, and wideLines, largePoints, shaderClipDistance,
     * fillModeNonSolid and logicOp, each where the device has it, with the extension names to
     * enable (a struct whose extension the device lacks is taken out of the chain). It says which FFVK_FEATURE_* bits the device will then have: what
     * FfvkRendererCreateInfo::enabled_features says (Vulkan cannot tell ffvk what a device
     * was created with). */
    VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT non_seamless = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT,
    };
    VkPhysicalDeviceLineRasterizationFeaturesEXT lines = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
        .pNext = &non_seamless,
    };
    VkPhysicalDeviceProvokingVertexFeaturesEXT provoking = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
        .pNext = &lines,
    };
    VkPhysicalDeviceVulkan13Features v13 = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
        .pNext = &provoking,
        .synchronization2 = VK_TRUE,
    };
    VkPhysicalDeviceFeatures2 features = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
        .pNext = &v13,
    };
    /* This program enables no extension of its own: all the room is ffvk's. */
    const char *extensions[FFVK_MAX_DEVICE_EXTENSIONS];
    uint32_t extension_count = FFVK_MAX_DEVICE_EXTENSIONS;
    FFVK_CHECK(ffvkDeviceRequirements(vkGetInstanceProcAddr, app->instance, app->physical,
                                      &features, &extension_count, extensions,
                                      &app->ffvk_features));
    /* What the device lacks (GL_FLAT below needs FFVK_FEATURE_PROVOKING_VERTEX_LAST). */
    if (ffvkResultMessage()[0] != '\0')
        fprintf(stderr, "teapot: %s\n", ffvkResultMessage());
    VkDeviceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = &features,
        .queueCreateInfoCount = 1,
        .pQueueCreateInfos = &queue,
        .enabledExtensionCount = extension_count,
        .ppEnabledExtensionNames = extensions,
    };
    VK_CHECK(vkCreateDevice(app->physical, &info, NULL, &app->device));
    vkGetDeviceQueue(app->device, app->family, 0, &app->queue);

    VkCommandPoolCreateInfo pool = {
        .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
        .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
        .queueFamilyIndex = app->family,
    };
    VK_CHECK(vkCreateCommandPool(app->device, &pool, NULL, &app->pool));
    VkCommandBufferAllocateInfo alloc = {
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
        .commandPool = app->pool,
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
        .commandBufferCount = 1,
    };
    VK_CHECK(vkAllocateCommandBuffers(app->device, &alloc, &app->cmd));
    VkFenceCreateInfo fence = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(app->device, &fence, NULL, &app->fence));
}

/* Memory of a type the requirements allow with all of `flags`, or 0 if there is none. */
static VkDeviceMemory allocate(App *app, VkMemoryRequirements req, VkMemoryPropertyFlags flags) {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(app->physical, &props);
    for (uint32_t i = 0; i < props.memoryTypeCount; i++) {
        if ((req.memoryTypeBits & (1u << i)) &&
            (props.memoryTypes[i].propertyFlags & flags) == flags) {
            VkMemoryAllocateInfo info = {
                .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                .allocationSize = req.size,
                .memoryTypeIndex = i,
            };
            VkDeviceMemory memory;
            VK_CHECK(vkAllocateMemory(app->device, &info, NULL, &memory));
            return memory;
        }
    }
    return VK_NULL_HANDLE;
}

/* A host-visible buffer holding `size` bytes of `bytes` (zeros for null). Host-visible
 * vertex buffers keep the example short; ffvk reads whatever buffers a draw names. */
static Buffer create_buffer(App *app, const void *bytes, VkDeviceSize size,
                            VkBufferUsageFlags usage) {
    Buffer b;
    VkBufferCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size < 4 ? 4 : size,
        .usage = usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
    };
    VK_CHECK(vkCreateBuffer(app->device, &info, NULL, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(app->device, b.buffer, &req);
    b.memory = allocate(app, req,
                        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    if (!b.memory)
        die("no host-visible, coherent memory for a buffer");
    VK_CHECK(vkBindBufferMemory(app->device, b.buffer, b.memory, 0));
    void *mapped;
    VK_CHECK(vkMapMemory(app->device, b.memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    if (bytes)
        memcpy(mapped, bytes, (size_t)size);
    else
        memset(mapped, 0, (size_t)size);
    vkUnmapMemory(app->device, b.memory);
    return b;
}

static VkImageSubresourceRange whole(VkImageAspectFlags aspect) {
    VkImageSubresourceRange range = {
        .aspectMask = aspect,
        .baseMipLevel = 0,
        .levelCount = 1,
        .baseArrayLayer = 0,
        .layerCount = 1,
    };
    return range;
}

static Image create_image(App *app, VkFormat format, VkImageUsageFlags usage,
                          VkImageAspectFlags aspect) {
    Image im;
    VkImageCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = format,
        .extent = {SIZE, SIZE, 1},
        .mipLevels = 1,
        .arrayLayers = 1,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .tiling = VK_IMAGE_TILING_OPTIMAL,
        .usage = usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
    };
    VK_CHECK(vkCreateImage(app->device, &info, NULL, &im.image));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(app->device, im.image, &req);
    im.memory = allocate(app, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!im.memory)
        im.memory = allocate(app, req, 0);
    if (!im.memory)
        die("no memory for an image");
    VK_CHECK(vkBindImageMemory(app->device, im.image, im.memory, 0));
    VkImageViewCreateInfo view_info = {
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = im.image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D,
        .format = format,
        .subresourceRange = whole(aspect),
    };
    VK_CHECK(vkCreateImageView(app->device, &view_info, NULL, &im.view));
    return im;
}

static uint8_t unorm8(float c) {
    float clamped = c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
    return (uint8_t)roundf(clamped * 255.0f);
}

/* The teapot in this program's own vertex layout (any layout works: FfvkRendererCreateInfo
 * describes it): positions alone in binding 0; normals with RGBA8 colors interleaved in
 * binding 1, 16 bytes a vertex. */
static void create_scene(App *app) {
    FfvkMesh *mesh;
    FFVK_CHECK(ffvkCreateTeapot(12, &mesh));
    FfvkMeshArrays arrays;
    FFVK_CHECK(ffvkGetMeshArrays(mesh, &arrays));

    size_t n = arrays.vertex_count;
    uint8_t *normal_colors = malloc(n * 16);
    if (!normal_colors)
        die("out of memory");
    for (size_t i = 0; i < n; i++) {
        uint8_t *vertex = normal_colors + 16 * i;
        memcpy(vertex, arrays.normals + 3 * i, 12);
        for (size_t k = 0; k < 4; k++)
            vertex[12 + k] = unorm8(arrays.colors[4 * i + k]);
    }
    app->positions = create_buffer(app, arrays.positions, n * 12,
                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    app->normal_colors = create_buffer(app, normal_colors, n * 16,
                                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    app->indices = create_buffer(app, arrays.indices, (VkDeviceSize)arrays.index_count * 4,
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    app->index_count = arrays.index_count;
    free(normal_colors);
    /* The arrays were copied into the buffers: the host mesh can go. */
    ffvkDestroyMesh(mesh);

    app->readback = create_buffer(app, NULL, (VkDeviceSize)SIZE * SIZE * 4,
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    app->color = create_image(app, COLOR_FORMAT,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
    app->depth = create_image(app, DEPTH_FORMAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                              VK_IMAGE_ASPECT_DEPTH_BIT);
}

/* ffvk on this device. Its pipelines are made for this vertex layout and these attachment
 * formats; one renderer draws every mode. */
static FfvkRenderer *create_renderer(App *app) {
    const VkVertexInputBindingDescription bindings[2] = {
        {.binding = 0, .stride = 12, .inputRate = VK_VERTEX_INPUT_RATE_VERTEX},
        {.binding = 1, .stride = 16, .inputRate = VK_VERTEX_INPUT_RATE_VERTEX},
    };
    /* glColorPointer's array. Without one (color = NULL), every vertex takes the context's
     * current color, as after glColor. */
    const FfvkAttribute color = {.binding = 1, .offset = 12, .format = VK_FORMAT_R8G8B8A8_UNORM};
    FfvkRendererCreateInfo info = {
        .struct_size = sizeof(FfvkRendererCreateInfo),
        /* ffvk loads every Vulkan function through the application's loader: it links no
         * Vulkan library of its own. */
        .get_instance_proc_addr = vkGetInstanceProcAddr,
        .instance = app->instance,
        .physical_device = app->physical,
        .device = app->device,
        .enabled_features = app->ffvk_features, /* from ffvkDeviceRequirements */
        .color_format = COLOR_FORMAT,
        .depth_format = DEPTH_FORMAT,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .bindings = bindings,
        .binding_count = 2,
        .position = {.binding = 0, .offset = 0, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .normal = {.binding = 1, .offset = 0, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .color = &color,
        .texcoord = NULL,
        /* Each frame is waited for before the next is recorded: one slot is enough. */
        .frames_in_flight = 1,
        .set_index = 0,
        .pipeline_cache = VK_NULL_HANDLE,
    };
    FfvkRenderer *renderer;
    FFVK_CHECK(ffvkCreateRenderer(&info, &renderer));
    return renderer;
}

/* Begins the command buffer and this program's rendering pass (clear color and depth), with
 * the viewport and scissor ffvk's pipelines leave dynamic. */
static void begin(App *app) {
    VkImageMemoryBarrier2 barriers[2] = {
        {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
            .srcAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            .dstAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
            .newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = app->color.image,
            .subresourceRange = whole(VK_IMAGE_ASPECT_COLOR_BIT),
        },
        {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
            .srcAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                            VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            .dstAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
            .newLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = app->depth.image,
            .subresourceRange = whole(VK_IMAGE_ASPECT_DEPTH_BIT),
        },
    };
    VkDependencyInfo dependency = {
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = 2,
        .pImageMemoryBarriers = barriers,
    };
    VkRenderingAttachmentInfo color = {
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = app->color.view,
        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue.color.float32 = {CLEAR[0], CLEAR[1], CLEAR[2], CLEAR[3]},
    };
    VkRenderingAttachmentInfo depth = {
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = app->depth.view,
        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
        .clearValue.depthStencil = {.depth = 1.0f, .stencil = 0},
    };
    VkRect2D area = {.offset = {0, 0}, .extent = {SIZE, SIZE}};
    VkRenderingInfo rendering = {
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = area,
        .layerCount = 1,
        .colorAttachmentCount = 1,
        .pColorAttachments = &color,
        .pDepthAttachment = &depth,
    };
    /* No negative-height flip: ffvk turns GL's clip space (y up, z in [-w, w]) into Vulkan's
     * itself, so a plain viewport puts GL's bottom row at the bottom of the image. */
    VkViewport viewport = {
        .x = 0.0f,
        .y = 0.0f,
        .width = (float)SIZE,
        .height = (float)SIZE,
        .minDepth = 0.0f,
        .maxDepth = 1.0f,
    };
    VkCommandBufferBeginInfo begin_info = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};

    VK_CHECK(vkResetCommandBuffer(app->cmd, 0));
    VK_CHECK(vkBeginCommandBuffer(app->cmd, &begin_info));
    vkCmdPipelineBarrier2(app->cmd, &dependency);
    vkCmdBeginRendering(app->cmd, &rendering);
    vkCmdSetViewport(app->cmd, 0, 1, &viewport);
    vkCmdSetScissor(app->cmd, 0, 1, &area);
}

/* Ends the pass, copies the image out, submits, waits, and copies the pixels (RGBA8, top row
 * first) to `rgba`. */
static void finish(App *app, uint8_t *rgba) {
    VkImageMemoryBarrier2 to_transfer = {
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
        .srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        .srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
        .dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT,
        .oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        .newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = app->color.image,
        .subresourceRange = whole(VK_IMAGE_ASPECT_COLOR_BIT),
    };
    VkDependencyInfo image_dependency = {
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = 1,
        .pImageMemoryBarriers = &to_transfer,
    };
    VkBufferMemoryBarrier2 to_host = {
        .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
        .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
        .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
        .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .buffer = app->readback.buffer,
        .offset = 0,
        .size = VK_WHOLE_SIZE,
    };
    VkDependencyInfo buffer_dependency = {
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .bufferMemoryBarrierCount = 1,
        .pBufferMemoryBarriers = &to_host,
    };
    VkBufferImageCopy region = {
        .bufferOffset = 0,
        .imageSubresource = {.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT, .layerCount = 1},
        .imageExtent = {SIZE, SIZE, 1},
    };
    VkSubmitInfo submit = {
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
        .commandBufferCount = 1,
        .pCommandBuffers = &app->cmd,
    };

    vkCmdEndRendering(app->cmd);
    vkCmdPipelineBarrier2(app->cmd, &image_dependency);
    vkCmdCopyImageToBuffer(app->cmd, app->color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           app->readback.buffer, 1, &region);
    vkCmdPipelineBarrier2(app->cmd, &buffer_dependency);
    VK_CHECK(vkEndCommandBuffer(app->cmd));
    VK_CHECK(vkQueueSubmit(app->queue, 1, &submit, app->fence));
    VK_CHECK(vkWaitForFences(app->device, 1, &app->fence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(app->device, 1, &app->fence));

    void *mapped;
    VK_CHECK(vkMapMemory(app->device, app->readback.memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    memcpy(rgba, mapped, (size_t)SIZE * SIZE * 4);
    vkUnmapMemory(app->device, app->readback.memory);
}

/* One frame: the teapot under `ctx`'s state, into `rgba`. */
static void render(App *app, FfvkRenderer *renderer, const FfvkContext *ctx, uint8_t *rgba) {
    /* Slot 0's memory is free again: the last frame that used it was waited for. */
    FFVK_CHECK(ffvkBeginFrame(renderer, 0));
    begin(app);

    /* GL's raster state starts from GL's defaults (a zeroed struct is not them), with
     * glEnable(GL_DEPTH_TEST). */
    FfvkRaster raster;
    ffvkRasterDefaults(&raster);
    raster.depth_test = 1;
    const VkBuffer vertex_buffers[2] = {app->positions.buffer, app->normal_colors.buffer};
    FfvkDrawInfo draw = {
        .struct_size = sizeof(FfvkDrawInfo),
        .mode = GL_TRIANGLES,
        .vertex_buffers = vertex_buffers,
        .vertex_offsets = NULL,
        .vertex_buffer_count = 2,
        .index_buffer = app->indices.buffer,
        .index_offset = 0,
        .index_type = VK_INDEX_TYPE_UINT32,
        .first = 0,
        .count = app->index_count,
        .vertex_offset = 0,
        .primitive_restart = 0,
        .raster = raster,
        .texture = NULL,
    };
    /* A layer calls ffvkDraw for each glDrawElements between its own BeginDraws/EndDraws;
     * ffvkDraw copies the context's state, and ffvkEndDraws records the whole run. Nothing of
     * our own may be recorded into the command buffer in between. */
    FFVK_CHECK(ffvkBeginDraws(renderer, app->cmd, 0));
    FFVK_CHECK(ffvkDraw(renderer, ctx, &draw));
    FFVK_CHECK(ffvkEndDraws(renderer));

    finish(app, rgba);
}

/* Binary PPM: RGB, top row first; the alpha channel is dropped. */
static void write_ppm(const char *path, const uint8_t *rgba) {
    FILE *file = fopen(path, "wb");
    if (!file)
        die("cannot create %s", path);
    fprintf(file, "P6\n%u %u\n255\n", SIZE, SIZE);
    for (size_t i = 0; i < (size_t)SIZE * SIZE; i++)
        fwrite(rgba + 4 * i, 1, 3, file);
    if (fclose(file) != 0)
        die("cannot write %s", path);
}

static void destroy_buffer(App *app, Buffer *b) {
    vkDestroyBuffer(app->device, b->buffer, NULL);
    vkFreeMemory(app->device, b->memory, NULL);
}

static void destroy_image(App *app, Image *im) {
    vkDestroyImageView(app->device, im->view, NULL);
    vkDestroyImage(app->device, im->image, NULL);
    vkFreeMemory(app->device, im->memory, NULL);
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTPUT_DIRECTORY\n", argv[0]);
        return 2;
    }
    const char *out_dir = argv[1];
    const char *device_name = getenv("FFVK_DEVICE");
    const char *validation_env = getenv("FFVK_VALIDATION");
    int validation = validation_env && strcmp(validation_env, "0") != 0;

    App app;
    memset(&app, 0, sizeof app);
    create_instance(&app, validation);
    pick_device(&app, device_name ? device_name : "llvmpipe");
    create_device(&app);
    create_scene(&app);
    FfvkRenderer *renderer = create_renderer(&app);

    uint8_t *rgba = malloc((size_t)SIZE * SIZE * 4);
    if (!rgba)
        die("out of memory");
    for (size_t m = 0; m < sizeof MODES / sizeof MODES[0]; m++) {
        FfvkContext *ctx = teapot_state(&MODES[m]);
        render(&app, renderer, ctx, rgba);
        /* ffvkEndDraws took what it needed from the context. */
        ffvkDestroyContext(ctx);

        char path[4096];
        snprintf(path, sizeof path, "%s/teapot_%s.ppm", out_dir, MODES[m].name);
        write_ppm(path, rgba);
        printf("-> %s\n", path);
    }
    free(rgba);

    /* The renderer's objects live on our device: destroy it first, once nothing submitted
     * uses them (every frame was waited for; the idle wait says so to the validation layer's
     * satisfaction too). */
    VK_CHECK(vkDeviceWaitIdle(app.device));
    ffvkDestroyRenderer(renderer);
    destroy_image(&app, &app.color);
    destroy_image(&app, &app.depth);
    destroy_buffer(&app, &app.positions);
    destroy_buffer(&app, &app.normal_colors);
    destroy_buffer(&app, &app.indices);
    destroy_buffer(&app, &app.readback);
    vkDestroyFence(app.device, app.fence, NULL);
    vkDestroyCommandPool(app.device, app.pool, NULL);
    vkDestroyDevice(app.device, NULL);
    if (app.messenger) {
        PFN_vkDestroyDebugUtilsMessengerEXT destroy = (PFN_vkDestroyDebugUtilsMessengerEXT)
            vkGetInstanceProcAddr(app.instance, "vkDestroyDebugUtilsMessengerEXT");
        if (destroy)
            destroy(app.instance, app.messenger, NULL);
    }
    vkDestroyInstance(app.instance, NULL);

    if (validation_messages > 0) {
        fprintf(stderr, "teapot: %u validation message(s)\n", validation_messages);
        return 1;
    }
    return 0;
}
