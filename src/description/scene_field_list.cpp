#include "description/scene_field_list.h"

#include "description/scene_fields.h"

namespace urbis {

namespace {

/// Notes each field visitSceneFields names with its path, entering every optional object.
class FieldLister {
public:
    std::vector<FieldAtPath> fields;

    template <typename F>
    void object(const char* key, F&& visit) {
        path_.emplace_back(key);
        visit();
        path_.pop_back();
    }

    template <typename T, typename F>
    void optionalObject(const Field& f, std::optional<T>& value, F&& visit) {
        note(f);
        if (!value) value.emplace();
        object(f.key, [&] { visit(*value); });
    }

    template <typename... Rest>
    void number(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void vec3(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void optionalVec3(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void optionalArray(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void text(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void boolean(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void choice(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void choiceList(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void enumeration(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void colourMap(const Field& f, Rest&&...) { note(f); }
    template <typename... Rest>
    void keyframes(const Field& f, Rest&&...) { note(f); }

private:
    void note(const Field& f) {
        std::string path;
        for (const std::string& key : path_) path += key + ".";
        fields.push_back({path + f.key, f});
    }

    std::vector<std::string> path_;
};

} // namespace

const std::vector<FieldAtPath>& sceneFieldList() {
    static const std::vector<FieldAtPath> list = [] {
        SceneDescription scratch;
        FieldLister lister;
        visitSceneFields(scratch, lister);
        return lister.fields;
    }();
    return list;
}

} // namespace urbis
