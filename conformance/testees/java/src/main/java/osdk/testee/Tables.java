package osdk.testee;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * generated/tables/osdk_tables.json (bundled in the jar): what the testee
 * needs besides the library (the value model, control mode classes and ranges). Read once; every accessor is a plain lookup.
 */
final class Tables {
    static final Tables INSTANCE = load();

    /** One field of a ksy type as the value model shows it. */
    static final class Field {
        final String id;
        final String kind; // int, bits, bool, float, bytes, struct, switch
        final int width; // bytes, for int and float
        final int widthBits; // for bits and bool
        final boolean signed;
        final String enumKey; // null when not an enum
        final boolean optional;
        final boolean repeat;
        final String accessor; // the generated Java getter

        Field(Map<String, Object> m) {
            id = (String) m.get("id");
            kind = (String) m.get("kind");
            width = intOr(m.get("width"), 0);
            widthBits = intOr(m.get("width_bits"), 0);
            signed = Boolean.TRUE.equals(m.get("signed"));
            enumKey = (String) m.get("enum");
            optional = Boolean.TRUE.equals(m.get("optional"));
            repeat = Boolean.TRUE.equals(m.get("repeat"));
            accessor = lowerCamel(id);
        }
    }

    /** A ksy type: its seq ids (for "/seq/N") and the fields the model shows. */
    static final class Type {
        final String key;
        final List<String> seq;
        final List<Field> fields;
        final Map<String, String> conditions; // field id -> ksy `if` expression

        Type(String key, List<String> seq, List<Field> fields, Map<String, String> conditions) {
            this.key = key;
            this.seq = seq;
            this.fields = fields;
            this.conditions = conditions;
        }
    }

    /** Classification of one control mode byte on one profile. */
    static final class Mode {
        final String classification;
        final Long combination;

        Mode(Map<String, Object> m) {
            classification = (String) m.get("classification");
            Object c = m.get("combination");
            combination = c == null ? null : ((Number) c).longValue();
        }
    }

    /** min/max of one setpoint; null is unbounded. */
    static final class Range {
        final Double min;
        final Double max;

        Range(Map<String, Object> m) {
            min = m.get("min") == null ? null : ((Number) m.get("min")).doubleValue();
            max = m.get("max") == null ? null : ((Number) m.get("max")).doubleValue();
        }
    }

    final List<String> profiles;
    private final Map<String, Type> typesByClass = new HashMap<>();
    private final Map<String, Map<Long, String>> enums = new HashMap<>();
    private final Map<String, List<Mode>> modes = new HashMap<>();
    private final Map<String, Map<String, Map<String, Range>>> ranges = new HashMap<>();

    @SuppressWarnings("unchecked")
    private Tables(Map<String, Object> root) {
        profiles = Collections.unmodifiableList((List<String>) (List<?>) root.get("profiles"));
        Map<String, Object> model = (Map<String, Object>) root.get("model");
        Map<String, Object> ifs = (Map<String, Object>) root.get("if_expressions");
        for (Map.Entry<String, Object> e : ((Map<String, Object>) model.get("types")).entrySet()) {
            Map<String, Object> t = (Map<String, Object>) e.getValue();
            List<Field> fields = new ArrayList<>();
            for (Object f : (List<?>) t.get("fields")) {
                fields.add(new Field((Map<String, Object>) f));
            }
            Map<String, String> conds = ifs == null ? null : (Map<String, String>) ifs.get(e.getKey());
            Type type = new Type(e.getKey(), (List<String>) (List<?>) t.get("seq"), fields,
                    conds == null ? Collections.emptyMap() : conds);
            typesByClass.put(String.join("$", (List<String>) (List<?>) t.get("class_path")), type);
        }
        for (Map.Entry<String, Object> e : ((Map<String, Object>) model.get("enums")).entrySet()) {
            Map<Long, String> names = new HashMap<>();
            for (Map.Entry<String, Object> v : ((Map<String, Object>) e.getValue()).entrySet()) {
                names.put(Long.parseLong(v.getKey()), (String) v.getValue());
            }
            enums.put(e.getKey(), names);
        }
        Map<String, Object> cm = (Map<String, Object>) root.get("control_modes");
        for (Map.Entry<String, Object> e : cm.entrySet()) {
            Map<String, Object> p = (Map<String, Object>) e.getValue();
            List<Mode> list = new ArrayList<>();
            for (Object m : (List<?>) p.get("modes")) {
                list.add(new Mode((Map<String, Object>) m));
            }
            modes.put(e.getKey(), list);
            Map<String, Map<String, Range>> byCombination = new HashMap<>();
            for (Map.Entry<String, Object> r : ((Map<String, Object>) p.get("ranges")).entrySet()) {
                Map<String, Range> axes = new HashMap<>();
                for (Map.Entry<String, Object> a : ((Map<String, Object>) r.getValue()).entrySet()) {
                    axes.put(a.getKey(), new Range((Map<String, Object>) a.getValue()));
                }
                byCombination.put(r.getKey(), axes);
            }
            ranges.put(e.getKey(), byCombination);
        }
    }

    @SuppressWarnings("unchecked")
    private static Tables load() {
        try (InputStream in = Tables.class.getResourceAsStream("/osdk_tables.json")) {
            if (in == null) {
                throw new IllegalStateException("osdk_tables.json is not in the jar");
            }
            return new Tables((Map<String, Object>) Json.parse(new String(in.readAllBytes(), StandardCharsets.UTF_8)));
        } catch (IOException e) {
            throw new IllegalStateException("cannot read osdk_tables.json: " + e.getMessage(), e);
        }
    }

    /** The ksy type of a generated class (osdk_kaitai.OsdkFrame$FrameData -> osdk_frame.frame_data). */
    Type typeOf(Class<?> cls) {
        String name = cls.getName();
        Type t = typesByClass.get(name.substring(name.lastIndexOf('.') + 1));
        if (t == null) {
            throw new IllegalStateException("no table entry for the generated class " + name);
        }
        return t;
    }

    /** The spec's name of an enum value, or null when it has none. */
    String enumName(String enumKey, long value) {
        Map<Long, String> names = enums.get(enumKey);
        if (names == null) {
            throw new IllegalStateException("no enum " + enumKey + " in the tables");
        }
        return names.get(value);
    }

    Mode mode(String profile, int modeByte) {
        return modes.get(profile).get(modeByte);
    }

    Range range(String profile, long combination, String axis) {
        return ranges.get(profile).get(Long.toString(combination)).get(axis);
    }

    private static int intOr(Object v, int fallback) {
        return v == null ? fallback : ((Number) v).intValue();
    }

    /** Kaitai's Java names: snake_case ids become lowerCamelCase getters. */
    static String lowerCamel(String id) {
        StringBuilder sb = new StringBuilder();
        boolean upper = false;
        for (char c : id.toCharArray()) {
            if (c == '_') {
                upper = sb.length() > 0;
                if (sb.length() == 0) {
                    sb.append('_');
                }
                continue;
            }
            sb.append(upper ? Character.toUpperCase(c) : c);
            upper = false;
        }
        return sb.toString();
    }
}
