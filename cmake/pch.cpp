// The host of the precompiled header every target reuses (cmake/precompiled_headers.cmake).
