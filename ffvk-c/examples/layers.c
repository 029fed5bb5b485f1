/* layers.c: what an emulation layer hands ffvk from one GL frame, through the C API.
 *
 * GL draws each call with whatever arrays the application enabled, its current values for the
 * rest, and glMaterial calls between glBegin and glEnd; it changes the viewport between draws.
 * One FfvkRenderer draws all of it: three vertex layouts in one frame (float normals, GL_BYTE
 * normals, a color array with a per-vertex emission material and no normals at all, which
 * takes the context's current normal), each draw in a viewport of its own set between ffvk's
 * recording scopes from GL's glViewport numbers (ffvkViewport), the last one not covering the
 * image's full height. The frame is written as a binary PPM:
 *
 *     make -C ffvk-c/examples run          # out/teapot_*.ppm and out/layers.ppm
 *     ./layers DIR                         # DIR/layers.ppm
 *
 * The test suite (tests/suite/c_api_layers.rs) builds and runs it with the validation layer on
 * and compares the image with Mesa's GL issuing the GL calls the comments below name.
 * Environment: FFVK_DEVICE and FFVK_VALIDATION, as for teapot.c. */

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <vulkan/vulkan.h>

#include "ffvk.h"

#define SIZE 96u
static const float CLEAR[4] = {0.0f, 0.0f, 0.0f, 0.0f};
#define COLOR_FORMAT VK_FORMAT_R8G8B8A8_UNORM
#define DEPTH_FORMAT VK_FORMAT_D32_SFLOAT

/* ------------------------------------------------------------------------------------------
 * Failing loudly. An example exits on the first failure; a layer would turn these into GL
 * errors or its own reporting instead. */

static void die(const char *format, ...) {
    va_list args;
    va_start(args, format);
    fputs("layers: ", stderr);
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

    /* One vertex buffer per layout (see create_scene), and the image read back. */
    Buffer floats, bytes, colored, readback;
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
        fprintf(stderr, "layers: validation: %s\n", data->pMessage);
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
        .pApplicationName = "ffvk layers.c",
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
        fprintf(stderr, "layers: %s\n", ffvkResultMessage());
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

/* A quad over its whole viewport as a triangle strip, z = 0, in three layouts. */
static const float QUAD[4][3] = {{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}};

/* Layout C's per-vertex colors (glColor4ub) and emissions (glMaterialfv(GL_EMISSION) between
 * glBegin and glEnd). */
static const uint8_t COLORS[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
static const float EMISSIONS[4][4] = {{0.2f, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0.2f, 1}, {0.1f, 0.1f, 0.1f, 1}};

/* The three vertex buffers:
 * A, 24 bytes a vertex: x y z, then a float normal (glNormalPointer(GL_FLOAT));
 * B, 16 bytes: x y z, then a GL_BYTE normal padded to four bytes, all zero (GL 2.1 reads each
 *    byte 0 as 1/255: a large diffuse material shows it);
 * C, 32 bytes: x y z, an RGBA8 color, then the emission material, four floats. */
static void create_scene(App *app) {
    float a[4][6];
    uint8_t b[4][16];
    uint8_t c[4][32];
    memset(b, 0, sizeof b);
    for (int i = 0; i < 4; i++) {
        const float normal[3] = {0, 0, 1};
        memcpy(a[i], QUAD[i], 12);
        memcpy(a[i] + 3, normal, 12);
        memcpy(b[i], QUAD[i], 12);
        memcpy(c[i], QUAD[i], 12);
        memcpy(c[i] + 12, COLORS[i], 4);
        memcpy(c[i] + 16, EMISSIONS[i], 16);
    }
    app->floats = create_buffer(app, a, sizeof a, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    app->bytes = create_buffer(app, b, sizeof b, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    app->colored = create_buffer(app, c, sizeof c, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    app->readback = create_buffer(app, NULL, (VkDeviceSize)SIZE * SIZE * 4,
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    app->color = create_image(app, COLOR_FORMAT,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
    app->depth = create_image(app, DEPTH_FORMAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                              VK_IMAGE_ASPECT_DEPTH_BIT);
}

static VkVertexInputBindingDescription binding0(uint32_t stride) {
    VkVertexInputBindingDescription b = {
        .binding = 0, .stride = stride, .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
    return b;
}

/* The renderer, made with layout A; layouts B and C added to it. */
static FfvkRenderer *create_renderer(App *app, FfvkVertexLayout **b, FfvkVertexLayout **c) {
    const VkVertexInputBindingDescription floats = binding0(24);
    FfvkRendererCreateInfo info = {
        .struct_size = sizeof(FfvkRendererCreateInfo),
        .get_instance_proc_addr = vkGetInstanceProcAddr,
        .instance = app->instance,
        .physical_device = app->physical,
        .device = app->device,
        .enabled_features = app->ffvk_features,
        .color_format = COLOR_FORMAT,
        .depth_format = DEPTH_FORMAT,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .bindings = &floats,
        .binding_count = 1,
        .position = {.binding = 0, .offset = 0, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .normal = {.binding = 0, .offset = 12, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .color = NULL,
        .texcoord = NULL,
        .frames_in_flight = 1,
        .set_index = 0,
        .pipeline_cache = VK_NULL_HANDLE,
    };
    FfvkRenderer *renderer;
    FFVK_CHECK(ffvkCreateRenderer(&info, &renderer));

    /* glNormalPointer(GL_BYTE, 16, 12): Vulkan does not require the three-byte format, so the
     * four-byte one with padding; ffvk converts as GL 2.1 does, (2c + 1)/255. */
    const VkVertexInputBindingDescription bytes = binding0(16);
    const FfvkAttribute byte_normal = {.binding = 0, .offset = 12, .format = VK_FORMAT_R8G8B8A8_SNORM};
    FfvkVertexLayoutInfo layout_b = {
        .struct_size = sizeof(FfvkVertexLayoutInfo),
        .bindings = &bytes,
        .binding_count = 1,
        .position = {.binding = 0, .offset = 0, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .normal = &byte_normal,
    };
    FFVK_CHECK(ffvkCreateVertexLayout(renderer, &layout_b, b));

    /* glColorPointer(4, GL_UNSIGNED_BYTE, 32, 12), no normal array (the current normal), and
     * the emission Mesa would keep per vertex for glMaterialfv inside glBegin/glEnd. */
    const VkVertexInputBindingDescription colored = binding0(32);
    const FfvkAttribute color = {.binding = 0, .offset = 12, .format = VK_FORMAT_R8G8B8A8_UNORM};
    const FfvkMaterialAttribute emission = {
        .face = GL_FRONT_AND_BACK,
        .pname = GL_EMISSION,
        .attribute = {.binding = 0, .offset = 16, .format = VK_FORMAT_R32G32B32A32_SFLOAT},
    };
    FfvkVertexLayoutInfo layout_c = {
        .struct_size = sizeof(FfvkVertexLayoutInfo),
        .bindings = &colored,
        .binding_count = 1,
        .position = {.binding = 0, .offset = 0, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .normal = NULL,
        .color = &color,
        .materials = &emission,
        .material_count = 1,
    };
    FFVK_CHECK(ffvkCreateVertexLayout(renderer, &layout_c, c));
    return renderer;
}

/* glViewport(x, y, width, height) as the layer records it: between ffvk's scopes. */
static void gl_viewport(App *app, int32_t x, int32_t y, int32_t width, int32_t height) {
    VkViewport viewport;
    FFVK_CHECK(ffvkViewport(x, y, width, height, SIZE, 0.0, 1.0, &viewport));
    vkCmdSetViewport(app->cmd, 0, 1, &viewport);
}

/* One glDrawArrays(GL_TRIANGLE_STRIP, 0, 4) from `buffer` in `layout` (NULL: the renderer's),
 * in a scope of its own. */
static void draw_quad(App *app, FfvkRenderer *renderer, const FfvkContext *ctx, VkBuffer buffer,
                      const FfvkVertexLayout *layout) {
    FfvkRaster raster;
    ffvkRasterDefaults(&raster);
    FfvkDrawInfo draw = {
        .struct_size = sizeof(FfvkDrawInfo),
        .mode = GL_TRIANGLE_STRIP,
        .vertex_buffers = &buffer,
        .vertex_buffer_count = 1,
        .index_buffer = VK_NULL_HANDLE,
        .first = 0,
        .count = 4,
        .raster = raster,
        .texture = NULL,
        .layout = layout,
    };
    FFVK_CHECK(ffvkBeginDraws(renderer, app->cmd, 0));
    FFVK_CHECK(ffvkDraw(renderer, ctx, &draw));
    FFVK_CHECK(ffvkEndDraws(renderer));
}

/* The frame, into `rgba`. */
static void render(App *app, FfvkRenderer *renderer, FfvkVertexLayout *layout_b,
                   FfvkVertexLayout *layout_c, uint8_t *rgba) {
    FfvkContext *ctx = ffvkCreateContext();
    if (!ctx)
        die("ffvkCreateContext: %s", ffvkResultMessage());
    ffvkEnable(ctx, GL_LIGHTING);
    ffvkEnable(ctx, GL_LIGHT0);
    check_gl(ctx, "the lights");

    FFVK_CHECK(ffvkBeginFrame(renderer, 0));
    begin(app);
    const int32_t third = (int32_t)SIZE / 3;

    /* glViewport(0, 0, third, SIZE); glNormalPointer(GL_FLOAT); glDrawArrays. */
    gl_viewport(app, 0, 0, third, (int32_t)SIZE);
    draw_quad(app, renderer, ctx, app->floats.buffer, NULL);

    /* glViewport(third, 0, third, SIZE); glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, ...);
     * glNormalPointer(GL_BYTE); glDrawArrays. */
    gl_viewport(app, third, 0, third, (int32_t)SIZE);
    const float strong[4] = {100.0f, 50.0f, 100.0f, 1.0f};
    ffvkMaterialfv(ctx, GL_FRONT_AND_BACK, GL_DIFFUSE, strong);
    draw_quad(app, renderer, ctx, app->bytes.buffer, layout_b);

    /* glViewport(2 third, third / 2, third, SIZE - third): not the full height, rows counted
     * from the bottom; glEnable(GL_COLOR_MATERIAL); glNormal3f(0, 0.6, 0.8); a color array and
     * the emission per vertex; glDrawArrays. */
    gl_viewport(app, 2 * third, third / 2, third, (int32_t)SIZE - third);
    ffvkEnable(ctx, GL_COLOR_MATERIAL);
    ffvkNormal3f(ctx, 0.0f, 0.6f, 0.8f);
    check_gl(ctx, "the third draw's state");
    draw_quad(app, renderer, ctx, app->colored.buffer, layout_c);

    finish(app, rgba);
    ffvkDestroyContext(ctx);
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
    const char *device_name = getenv("FFVK_DEVICE");
    const char *validation_env = getenv("FFVK_VALIDATION");
    int validation = validation_env && strcmp(validation_env, "0") != 0;

    App app;
    memset(&app, 0, sizeof app);
    create_instance(&app, validation);
    pick_device(&app, device_name ? device_name : "llvmpipe");
    create_device(&app);
    create_scene(&app);
    FfvkVertexLayout *layout_b, *layout_c;
    FfvkRenderer *renderer = create_renderer(&app, &layout_b, &layout_c);

    uint8_t *rgba = malloc((size_t)SIZE * SIZE * 4);
    if (!rgba)
        die("out of memory");
    render(&app, renderer, layout_b, layout_c, rgba);
    char path[4096];
    snprintf(path, sizeof path, "%s/layers.ppm", argv[1]);
    write_ppm(path, rgba);
    printf("-> %s\n", path);
    free(rgba);

    VK_CHECK(vkDeviceWaitIdle(app.device));
    ffvkDestroyVertexLayout(layout_b);
    ffvkDestroyVertexLayout(layout_c);
    ffvkDestroyRenderer(renderer);
    destroy_image(&app, &app.color);
    destroy_image(&app, &app.depth);
    destroy_buffer(&app, &app.floats);
    destroy_buffer(&app, &app.bytes);
    destroy_buffer(&app, &app.colored);
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
        fprintf(stderr, "layers: %u validation message(s)\n", validation_messages);
        return 1;
    }
    return 0;
}
