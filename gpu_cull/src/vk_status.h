// Turning VkResult into lintel::Status: one line naming the call, the result and what it was for.
#pragma once

#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <string_view>

namespace lintel::gpu {

const char* vk_result_name(VkResult result);

// Success for VK_SUCCESS; otherwise "<call> failed with <RESULT> (<what>)".
Status vk_check(VkResult result, std::string_view call, std::string_view what);

}  // namespace lintel::gpu
