package osdk.testee;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Reads the generated objects through their public getters, by ksy id: the
 * tables name the fields, Kaitai's Java target names the getters
 * lowerCamelCase after them.
 */
final class Accessors {
    private static final Map<Class<?>, Map<String, Method>> CACHE = new ConcurrentHashMap<>();

    private Accessors() {
    }

    static Object get(Object obj, String getter) {
        Method m = CACHE.computeIfAbsent(obj.getClass(), c -> new HashMap<>())
                .computeIfAbsent(getter, g -> lookup(obj.getClass(), g));
        try {
            return m.invoke(obj);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("cannot call " + getter + "() of " + obj.getClass().getName(), e);
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException) {
                throw (RuntimeException) cause;
            }
            throw new IllegalStateException(cause);
        }
    }

    /** The number a generated Java enum constant stands for (its id()). */
    static long enumId(Object constant) {
        return ((Number) get(constant, "id")).longValue();
    }

    private static Method lookup(Class<?> cls, String getter) {
        try {
            return cls.getMethod(getter);
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException("the generated class " + cls.getName() + " has no " + getter + "()");
        }
    }
}
