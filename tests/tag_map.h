// Tags as tests write them: a map seen through a TagLookup.
#pragma once

#include "osm/tag_lookup.h"

#include <map>
#include <string>

namespace urbis::test {

/// A TagLookup over `tags`, which must outlive it.
inline TagLookup tagsOf(const std::map<std::string, std::string>& tags) {
    return [&tags](const char* key) -> const char* {
        const auto it = tags.find(key);
        return it == tags.end() ? nullptr : it->second.c_str();
    };
}

} // namespace urbis::test
