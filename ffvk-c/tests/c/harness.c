/* harness.c: see harness.h. */

#include "harness.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void die(const char *format, ...) {
    va_list args;
    va_start(args, format);
    fputs("ffvk test program: ", stderr);
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

/* ------------------------------------------------------------------------------------------
 * Scenes. */

static void expect_word(FILE *file, const char *word, const char *path) {
    char read[16];
    if (fscanf(file, "%15s", read) != 1 || strcmp(read, word) != 0)
        die("%s: expected \"%s\"", path, word);
}

void scene_read(const char *path, Scene *scene) {
    FILE *file = fopen(path, "r");
    if (!file)
        die("cannot open the scene %s", path);
    memset(scene, 0, sizeof *scene);
    expect_word(file, "target", path);
    if (fscanf(file, "%u %u", &scene->width, &scene->height) != 2)
        die("%s: expected the target's width and height", path);
    expect_word(file, "clear", path);
    if (fscanf(file, "%f %f %f %f %f", &scene->clear_color[0], &scene->clear_color[1],
               &scene->clear_color[2], &scene->clear_color[3], &scene->clear_depth) != 5)
        die("%s: expected the clear color and depth", path);
    char word[16];
    while (fscanf(file, "%15s", word) == 1) {
        if (strcmp(word, "raster") == 0 && scene->draw_count > 0) {
            SceneRaster *r = &scene->draws[scene->draw_count - 1].raster;
            if (fscanf(file, "%u %u %u %u %u %u %u %u %u %u %u %u %u", &r->color_mask[0],
                       &r->color_mask[1], &r->color_mask[2], &r->color_mask[3],
                       &r->stencil_test, &r->stencil_func, &r->stencil_ref, &r->stencil_mask,
                       &r->stencil_ops[0], &r->stencil_ops[1], &r->stencil_ops[2],
                       &r->logic_op_enabled, &r->logic_op) != 13)
                die("%s: draw %u: expected its raster state", path, scene->draw_count - 1);
            continue;
        }
        if (strcmp(word, "draw") != 0)
            die("%s: \"%s\": expected \"draw\" or \"raster\"", path, word);
        if (scene->draw_count == SCENE_MAX_DRAWS)
            die("%s: more than %u draws", path, SCENE_MAX_DRAWS);
        SceneDraw *d = &scene->draws[scene->draw_count++];
        if (fscanf(file, "%d %d %d %d %lf %lf %d %d %d %d %f %f %f %f %u", &d->viewport[0],
                   &d->viewport[1], &d->viewport[2], &d->viewport[3], &d->depth_range[0],
                   &d->depth_range[1], &d->scissor[0], &d->scissor[1], &d->scissor[2],
                   &d->scissor[3], &d->color[0], &d->color[1], &d->color[2], &d->color[3],
                   &d->count) != 15)
            die("%s: draw %u: expected its viewport, depth range, scissor, color and count",
                path, scene->draw_count - 1);
        if (d->count > SCENE_MAX_VERTICES - scene->vertex_count)
            die("%s: more than %u vertices", path, SCENE_MAX_VERTICES);
        /* GL's initial state (tables 6.20 and 6.21): all colors written, GL_ALWAYS 0 with
         * all ones in the mask, GL_KEEP, GL_COPY. */
        const SceneRaster initial = {{1, 1, 1, 1}, 0, 0x0207, 0, 0xFFFFFFFFu,
                                     {0x1E00, 0x1E00, 0x1E00}, 0, 0x1503};
        d->raster = initial;
        d->first = scene->vertex_count;
        for (uint32_t i = 0; i < d->count; i++) {
            float *v = scene->vertices[scene->vertex_count++];
            if (fscanf(file, "%f %f %f", &v[0], &v[1], &v[2]) != 3)
                die("%s: draw %u: expected %u vertices", path, scene->draw_count - 1, d->count);
            v[3] = 0.0f;
            v[4] = 0.0f;
            v[5] = 1.0f;
        }
    }
    fclose(file);
    if (scene->width == 0 || scene->height == 0 || scene->draw_count == 0)
        die("%s: an empty target or no draws", path);
}

/* ------------------------------------------------------------------------------------------
 * Vulkan. */

static unsigned validation_messages = 0;

static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
    const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    (void)type;
    (void)user;
    if (severity & (VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)) {
        validation_messages++;
        fprintf(stderr, "ffvk test program: validation: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

void app_create_instance(App *app) {
    memset(app, 0, sizeof *app);
    VkApplicationInfo application = {
        .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
        .pApplicationName = "ffvk C API test",
        .apiVersion = VK_API_VERSION_1_3,
    };
    const char *layers[] = {"VK_LAYER_KHRONOS_validation"};
    const char *extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    VkInstanceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        .pApplicationInfo = &application,
        .enabledLayerCount = 1,
        .ppEnabledLayerNames = layers,
        .enabledExtensionCount = 1,
        .ppEnabledExtensionNames = extensions,
    };
    VK_CHECK(vkCreateInstance(&info, NULL, &app->instance));
    VkDebugUtilsMessengerCreateInfoEXT messenger = {
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
        .pfnUserCallback = on_message,
    };
    PFN_vkCreateDebugUtilsMessengerEXT create = (PFN_vkCreateDebugUtilsMessengerEXT)
        vkGetInstanceProcAddr(app->instance, "vkCreateDebugUtilsMessengerEXT");
    if (!create)
        die("vkCreateDebugUtilsMessengerEXT is missing");
    VK_CHECK(create(app->instance, &messenger, NULL, &app->messenger));

    VkPhysicalDevice physicals[16];
    uint32_t count = 16;
    VkResult listed = vkEnumeratePhysicalDevices(app->instance, &count, physicals);
    if (listed != VK_SUCCESS && listed != VK_INCOMPLETE)
        die("vkEnumeratePhysicalDevices: VkResult %d", (int)listed);
    for (uint32_t i = 0; i < count && !app->physical; i++) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(physicals[i], &props);
        if (strstr(props.deviceName, "llvmpipe"))
            app->physical = physicals[i];
    }
    if (!app->physical)
        die("no lavapipe (llvmpipe) device: install mesa-vulkan-drivers");
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

void app_create_device(App *app, const void *features, uint32_t extension_count,
                       const char *const *extensions) {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
        .queueFamilyIndex = app->family,
        .queueCount = 1,
        .pQueuePriorities = &priority,
    };
    VkDeviceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = features,
        .queueCreateInfoCount = 1,
        .pQueueCreateInfos = &queue,
        .enabledExtensionCount = extension_count,
        .ppEnabledExtensionNames = extensions,
    };
    VK_CHECK(vkCreateDevice(app->physical, &info, NULL, &app->device));
    vkGetDeviceQueue(app->device, app->family, 0, &app->queue);
    VkCommandPoolCreateInfo pool = {
        .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
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

/* Memory of a type the requirements allow with all of `flags`, or VK_NULL_HANDLE. */
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

Buffer app_buffer(App *app, const void *bytes, VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer b;
    VkBufferCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
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
        .extent = {app->width, app->height, 1},
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
    im.memory = allocate(app, req, 0);
    if (!im.memory)
        die("no memory for an image");
    VK_CHECK(vkBindImageMemory(app->device, im.image, im.memory, 0));
    VkImageViewCreateInfo view = {
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = im.image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D,
        .format = format,
        .subresourceRange = whole(aspect),
    };
    VK_CHECK(vkCreateImageView(app->device, &view, NULL, &im.view));
    return im;
}

/* The aspects of the depth attachment's format. */
static VkImageAspectFlags depth_aspects(VkFormat format) {
    switch (format) {
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    default:
        return VK_IMAGE_ASPECT_DEPTH_BIT;
    }
}

void app_create_targets(App *app, uint32_t width, uint32_t height) {
    app_create_targets_with(app, width, height, DEPTH_FORMAT);
}

void app_create_targets_with(App *app, uint32_t width, uint32_t height, VkFormat depth_format) {
    app->width = width;
    app->height = height;
    app->depth_format = depth_format;
    app->color = create_image(app, COLOR_FORMAT,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
    app->depth = create_image(app, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                              depth_aspects(depth_format));
    app->readback = app_buffer(app, NULL, (VkDeviceSize)width * height * 4,
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

/* One image barrier in the pipeline barrier's old style (Vulkan 1.0: synchronization2 is
 * not enabled by every program here). */
static void barrier(App *app, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                    VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access,
                    VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage) {
    VkImageMemoryBarrier b = {
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
        .srcAccessMask = src_access,
        .dstAccessMask = dst_access,
        .oldLayout = from,
        .newLayout = to,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = whole(aspect),
    };
    vkCmdPipelineBarrier(app->cmd, src_stage, dst_stage, 0, 0, NULL, 0, NULL, 1, &b);
}

void app_begin(App *app, const Scene *scene) {
    VkCommandBufferBeginInfo begin = {
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VK_CHECK(vkBeginCommandBuffer(app->cmd, &begin));
    barrier(app, app->color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    const VkImageAspectFlags aspects = depth_aspects(app->depth_format);
    const int stencil = (aspects & VK_IMAGE_ASPECT_STENCIL_BIT) != 0;
    const VkImageLayout depth_layout = stencil ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                                               : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    barrier(app, app->depth.image, aspects, VK_IMAGE_LAYOUT_UNDEFINED, depth_layout, 0,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT);
    VkRenderingAttachmentInfo color = {
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = app->color.view,
        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue.color.float32 = {scene->clear_color[0], scene->clear_color[1],
                                     scene->clear_color[2], scene->clear_color[3]},
    };
    VkRenderingAttachmentInfo depth = {
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = app->depth.view,
        .imageLayout = depth_layout,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
        .clearValue.depthStencil = {.depth = scene->clear_depth, .stencil = 0},
    };
    VkRenderingInfo rendering = {
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {.offset = {0, 0}, .extent = {app->width, app->height}},
        .layerCount = 1,
        .colorAttachmentCount = 1,
        .pColorAttachments = &color,
        .pDepthAttachment = &depth,
        /* The same view and clear (stencil 0) for the stencil aspect, where there is one. */
        .pStencilAttachment = stencil ? &depth : NULL,
    };
    vkCmdBeginRendering(app->cmd, &rendering);
}

void app_finish(App *app, const char *path) {
    vkCmdEndRendering(app->cmd);
    barrier(app, app->color.image, VK_IMAGE_ASPECT_COLOR_BIT,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region = {
        .imageSubresource = {.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT, .layerCount = 1},
        .imageExtent = {app->width, app->height, 1},
    };
    vkCmdCopyImageToBuffer(app->cmd, app->color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           app->readback.buffer, 1, &region);
    VkBufferMemoryBarrier to_host = {
        .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER,
        .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
        .dstAccessMask = VK_ACCESS_HOST_READ_BIT,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .buffer = app->readback.buffer,
        .size = VK_WHOLE_SIZE,
    };
    vkCmdPipelineBarrier(app->cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         0, NULL, 1, &to_host, 0, NULL);
    VK_CHECK(vkEndCommandBuffer(app->cmd));
    VkSubmitInfo submit = {
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
        .commandBufferCount = 1,
        .pCommandBuffers = &app->cmd,
    };
    VK_CHECK(vkQueueSubmit(app->queue, 1, &submit, app->fence));
    VK_CHECK(vkWaitForFences(app->device, 1, &app->fence, VK_TRUE, UINT64_MAX));

    const uint8_t *rgba;
    VK_CHECK(vkMapMemory(app->device, app->readback.memory, 0, VK_WHOLE_SIZE, 0,
                         (void **)&rgba));
    FILE *file = fopen(path, "wb");
    if (!file)
        die("cannot create %s", path);
    fprintf(file, "P6\n%u %u\n255\n", app->width, app->height);
    for (size_t i = 0; i < (size_t)app->width * app->height; i++)
        fwrite(rgba + 4 * i, 1, 3, file);
    if (fclose(file) != 0)
        die("cannot write %s", path);
    vkUnmapMemory(app->device, app->readback.memory);
}

void app_destroy_buffer(App *app, Buffer *buffer) {
    vkDestroyBuffer(app->device, buffer->buffer, NULL);
    vkFreeMemory(app->device, buffer->memory, NULL);
}

static void destroy_image(App *app, Image *im) {
    vkDestroyImageView(app->device, im->view, NULL);
    vkDestroyImage(app->device, im->image, NULL);
    vkFreeMemory(app->device, im->memory, NULL);
}

unsigned app_destroy(App *app) {
    VK_CHECK(vkDeviceWaitIdle(app->device));
    destroy_image(app, &app->color);
    destroy_image(app, &app->depth);
    app_destroy_buffer(app, &app->readback);
    vkDestroyFence(app->device, app->fence, NULL);
    vkDestroyCommandPool(app->device, app->pool, NULL);
    vkDestroyDevice(app->device, NULL);
    PFN_vkDestroyDebugUtilsMessengerEXT destroy = (PFN_vkDestroyDebugUtilsMessengerEXT)
        vkGetInstanceProcAddr(app->instance, "vkDestroyDebugUtilsMessengerEXT");
    if (destroy)
        destroy(app->instance, app->messenger, NULL);
    vkDestroyInstance(app->instance, NULL);
    return validation_messages;
}
