// Preloaded into `ispm view` by the viewer's leak check (sanitized builds only): Mesa's drivers
// stay loaded when the GL display closes, so what a driver keeps in its own globals stays
// reachable and LeakSanitizer can tell it from ispm's leaks. Unloaded, such memory shows as
// leaked from "<unknown module>", which no suppression can name. Other libraries unload as usual.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <link.h>
#include <string.h>

int dlclose(void* handle) {
    struct link_map* map = NULL;
    if (dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map && map->l_name &&
        strstr(map->l_name, "/dri/") != NULL) {
        return 0; // a Mesa driver (.../dri/swrast_dri.so): keep it
    }
    int (*realDlclose)(void*) = (int (*)(void*))dlsym(RTLD_NEXT, "dlclose");
    return realDlclose(handle);
}
