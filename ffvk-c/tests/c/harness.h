/* harness.h: the Vulkan side of the C API's test programs (abi_v1.c, viewport.c, raster.c), and the
 * scenes they draw. Plain C99 on Vulkan's C API; no ffvk here, so that each program includes
 * the ffvk.h it is about (today's, or version 1's).
 *
 * Every program runs with the Khronos validation layer on, and any message of warning or
 * error severity fails it (app_destroy returns how many there were). Any other failure ends
 * the program with a message on stderr and exit status 1. */

#ifndef FFVK_TEST_HARNESS_H
#define FFVK_TEST_HARNESS_H

#include <stdint.h>

#include <vulkan/vulkan.h>

#define SCENE_MAX_DRAWS 32u
#define SCENE_MAX_VERTICES 256u

/* GL's raster state for one draw (raster.c): glColorMask, glEnable(GL_STENCIL_TEST) with
 * glStencilFunc and glStencilOp, glEnable(GL_COLOR_LOGIC_OP) with glLogicOp; GL's enums as
 * numbers. Without a `raster` line, GL's initial state. */
typedef struct {
    uint32_t color_mask[4];
    uint32_t stencil_test, stencil_func, stencil_ref, stencil_mask, stencil_ops[3];
    uint32_t logic_op_enabled, logic_op;
} SceneRaster;

/* One draw of a scene: GL's glViewport, glDepthRange and glScissor (GL's window coordinates,
 * rows from the bottom), glColor4f, and a GL_TRIANGLE_FAN of `count` vertices from `first`,
 * given in GL's clip coordinates (the modelview and projection are the identity, lighting
 * is off); and the raster state raster.c sets before it (the other programs ignore it). */
typedef struct {
    int32_t viewport[4];
    double depth_range[2];
    int32_t scissor[4];
    float color[4];
    uint32_t first, count;
    SceneRaster raster;
} SceneDraw;

/* A scene file, as the tests write it (one item a line, numbers separated by spaces):
 *
 *     target WIDTH HEIGHT
 *     clear R G B A DEPTH
 *     draw VX VY VW VH NEAR FAR SX SY SW SH R G B A N X0 Y0 Z0 ... X(N-1) Y(N-1) Z(N-1)
 *     raster MR MG MB MA STENCIL FUNC REF MASK SFAIL DPFAIL DPPASS LOGIC OP   (optional)
 *
 * A `raster` line sets the raster state of the draw before it.
 * The depth test is on with GL_LESS, as after glEnable(GL_DEPTH_TEST). */
typedef struct {
    uint32_t width, height;
    float clear_color[4];
    float clear_depth;
    uint32_t draw_count;
    SceneDraw draws[SCENE_MAX_DRAWS];
    uint32_t vertex_count;
    /* Position x y z, then normal 0 0 1: the vertex layout the programs give ffvk. */
    float vertices[SCENE_MAX_VERTICES][6];
} Scene;

/* Reads the scene file at `path` into `scene`, or ends the program saying what is wrong. */
void scene_read(const char *path, Scene *scene);

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
    VkDebugUtilsMessengerEXT messenger;
    VkPhysicalDevice physical;
    VkDevice device;
    uint32_t family;
    VkQueue queue;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    VkFence fence;
    uint32_t width, height;
    Image color, depth;
    VkFormat depth_format;
    Buffer readback;
} App;

#define COLOR_FORMAT VK_FORMAT_R8G8B8A8_UNORM
#define DEPTH_FORMAT VK_FORMAT_D32_SFLOAT

/* Ends the program with a message (prefixed with the program's name) on stderr. */
void die(const char *format, ...);

/* An instance of API 1.3 with the validation layer and a messenger counting its messages,
 * and lavapipe ("llvmpipe") with a graphics queue family. */
void app_create_instance(App *app);

/* The device, with `features` (a VkPhysicalDeviceFeatures2 and its chain, or NULL) as
 * VkDeviceCreateInfo::pNext and the extensions named; its queue, command pool and buffer,
 * and fence. */
void app_create_device(App *app, const void *features, uint32_t extension_count,
                       const char *const *extensions);

/* The color (RGBA8) and depth (D32) attachments of `width` x `height` and the readback
 * buffer. */
void app_create_targets(App *app, uint32_t width, uint32_t height);

/* app_create_targets with the depth attachment in `depth_format` (one with stencil too, e.g.
 * VK_FORMAT_D24_UNORM_S8_UINT: app_begin then clears the stencil to 0 and renders to it). */
void app_create_targets_with(App *app, uint32_t width, uint32_t height, VkFormat depth_format);

/* A host-visible buffer holding `size` bytes of `bytes`. */
Buffer app_buffer(App *app, const void *bytes, VkDeviceSize size, VkBufferUsageFlags usage);

/* Begins the command buffer and a rendering pass on the attachments, cleared to the scene's
 * color and depth. Sets no viewport and no scissor: each program sets its own. */
void app_begin(App *app, const Scene *scene);

/* Ends the pass, copies the color attachment out, submits, waits, and writes the pixels
 * (RGB, top row first) to the binary PPM file `path`. */
void app_finish(App *app, const char *path);

void app_destroy_buffer(App *app, Buffer *buffer);

/* Destroys everything (the device waited idle first) and returns how many validation
 * messages there were. */
unsigned app_destroy(App *app);

#endif
