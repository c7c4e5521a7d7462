#pragma once
// The viewer's GLFW window: one window with no client API (Vulkan draws into it through a
// surface), its framebuffer size, and the input gathered between two frames. GLFW is
// initialised by the first Window and terminated by its destructor; there is only one.

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace agaa::viewer {

// GLFW could not start (no display, no Vulkan loader for GLFW, window creation refused).
// main() reports it and exits with code 3 instead of crashing.
class WindowError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Everything the user did since the last takeInput(), in window pixels and GLFW key codes.
struct InputEvents {
    double dragX = 0.0, dragY = 0.0; // cursor motion while the left button was held
    double scroll = 0.0;             // wheel steps, positive away from the user
    std::vector<int> keys;           // GLFW_KEY_* pressed (not repeats), in order
    bool resized = false;            // the framebuffer size changed
};

class Window {
  public:
    // Throws WindowError when GLFW cannot initialise or create the window.
    Window(uint32_t width, uint32_t height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Instance extensions the window system needs (VK_KHR_surface and its platform extension).
    std::vector<const char*> requiredInstanceExtensions() const;
    // The caller owns the surface and destroys it before the instance.
    VkSurfaceKHR createSurface(VkInstance instance) const;

    bool shouldClose() const;
    void requestClose();
    void pollEvents();
    // Blocks until something happens: used while minimised, where there is nothing to draw.
    void waitEvents();
    // In pixels; {0, 0} while minimised.
    VkExtent2D framebufferSize() const;
    bool minimised() const;
    void setTitle(const std::string& title);
    // For the UI's input backend, which installs its callbacks after the window's and chains to them.
    GLFWwindow* handle() const { return m_window; }
    InputEvents takeInput();

  private:
    static Window& self(GLFWwindow* window);
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onCursor(GLFWwindow* window, double x, double y);
    static void onButton(GLFWwindow* window, int button, int action, int mods);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onResize(GLFWwindow* window, int width, int height);

    GLFWwindow* m_window = nullptr;
    InputEvents m_input;
    bool m_dragging = false;
    double m_cursorX = 0.0, m_cursorY = 0.0;
};

} // namespace agaa::viewer
