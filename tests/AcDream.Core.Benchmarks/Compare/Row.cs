using System.Diagnostics;
using System.Globalization;
using System.Linq.Expressions;
using System.Reflection;
using System.Runtime.Loader;

namespace AcDream.Core.Benchmarks.Compare;

/// <summary>
/// One benchmark row (<c>Class.Method[@Param=Value,...]</c>) of one build's benchmark assembly, loaded into that build's
/// own load context: its parameters set, its <c>[GlobalSetup]</c> run, and its method timed per operation (its
/// <c>OperationsPerInvoke</c> honoured).
/// </summary>
internal sealed class Row
{
    private static readonly Dictionary<string, AssemblyLoadContext> Contexts = [];

    /// <summary>The benchmark objects made so far, by assembly, class and parameters: rows of one object share its setup.</summary>
    private static readonly Dictionary<string, object> Instances = [];

    /// <summary>The benchmark objects whose <c>[GlobalSetup]</c> has run.</summary>
    private static readonly HashSet<object> SetUp = new(ReferenceEqualityComparer.Instance);

    /// <summary>Where every call's result goes, so the work is never dead code.</summary>
    public static object? Sink;

    private readonly object _instance;
    private readonly Type _type;
    private readonly Func<object?> _call;
    private readonly int _operations;

    private Row(object instance, Type type, Func<object?> call, int operations)
        => (_instance, _type, _call, _operations) = (instance, type, call, operations);

    /// <summary>Loads <paramref name="spec"/> from the benchmark assembly <paramref name="dll"/>.</summary>
    public static Row Load(string dll, string spec)
    {
        string parameters = "";
        int at = spec.IndexOf('@', StringComparison.Ordinal);
        if (at >= 0)
        {
            (spec, parameters) = (spec[..at], spec[(at + 1)..]);
        }

        int dot = spec.LastIndexOf('.');
        if (dot <= 0)
        {
            throw new ArgumentException($"'{spec}' is not Class.Method");
        }

        string className = spec[..dot], methodName = spec[(dot + 1)..];
        Assembly assembly = ContextOf(dll).LoadFromAssemblyPath(dll);
        Type type = assembly.GetTypes().SingleOrDefault(t => t.Name == className)
            ?? throw new ArgumentException($"{Path.GetFileName(dll)} has no benchmark class {className}");
        string key = $"{dll}|{className}|{parameters}";
        if (!Instances.TryGetValue(key, out object? instance))
        {
            Instances[key] = instance = Activator.CreateInstance(type)!;
            foreach (string assignment in parameters.Split(',', StringSplitOptions.RemoveEmptyEntries))
            {
                string[] kv = assignment.Split('=', 2);
                Set(type, instance, kv[0], kv.Length == 2 ? kv[1] : throw new ArgumentException($"'{assignment}' is not Param=Value"));
            }
        }

        MethodInfo method = type.GetMethod(methodName, Type.EmptyTypes)
            ?? throw new ArgumentException($"{className} has no method {methodName}");
        Attribute? benchmark = method.GetCustomAttributes().FirstOrDefault(a => a.GetType().Name == "BenchmarkAttribute");
        int operations = benchmark is null ? 1 : (int)benchmark.GetType().GetProperty("OperationsPerInvoke")!.GetValue(benchmark)!;
        Func<object?> call = Expression.Lambda<Func<object?>>(
            Expression.Convert(Expression.Call(Expression.Constant(instance), method), typeof(object))).Compile();
        return new Row(instance, type, call, operations);
    }

    private static void Set(Type type, object instance, string name, string value)
    {
        if (type.GetProperty(name) is PropertyInfo property)
        {
            property.SetValue(instance, Convert(value, property.PropertyType));
        }
        else if (type.GetField(name) is FieldInfo field)
        {
            field.SetValue(instance, Convert(value, field.FieldType));
        }
        else
        {
            throw new ArgumentException($"{type.Name} has no parameter {name}");
        }
    }

    private static object Convert(string value, Type type)
        => type.IsEnum ? Enum.Parse(type, value) : System.Convert.ChangeType(value, type, CultureInfo.InvariantCulture);

    /// <summary>Runs the row's <c>[GlobalSetup]</c> methods, once per benchmark object; the fixtures are found beside the row's own assembly.</summary>
    public void Setup()
    {
        if (!SetUp.Add(_instance))
        {
            return;
        }

        AppContext.SetData("APP_CONTEXT_BASE_DIRECTORY", Path.GetDirectoryName(_type.Assembly.Location) + Path.DirectorySeparatorChar);
        foreach (MethodInfo m in _type.GetMethods().Where(m => m.GetCustomAttributes().Any(a => a.GetType().Name == "GlobalSetupAttribute")))
        {
            m.Invoke(_instance, null);
        }
    }

    /// <summary>How many invocations take about <paramref name="ms"/> milliseconds.</summary>
    public int Calibrate(double ms)
    {
        for (int n = 1; ; n *= 2)
        {
            double elapsedMs = Time(n) * n * _operations / 1e6;
            if (elapsedMs >= ms / 4 || n >= 1 << 24)
            {
                return Math.Max(1, (int)Math.Min(int.MaxValue, n * ms / Math.Max(elapsedMs, 1e-6)));
            }
        }
    }

    /// <summary>Nanoseconds per operation over <paramref name="invocations"/> invocations.</summary>
    public double Time(int invocations)
    {
        long start = Stopwatch.GetTimestamp();
        for (int i = 0; i < invocations; i++)
        {
            Sink = _call();
        }

        return Stopwatch.GetElapsedTime(start).TotalNanoseconds / ((double)invocations * _operations);
    }

    private static AssemblyLoadContext ContextOf(string dll)
    {
        string folder = Path.GetDirectoryName(dll)!;
        if (!Contexts.TryGetValue(folder, out AssemblyLoadContext? context))
        {
            Contexts[folder] = context = new BuildContext(dll);
        }

        return context;
    }

    /// <summary>One build's assemblies: resolved from its own folder first, so each side runs its own AcDream.Core.</summary>
    private sealed class BuildContext(string main) : AssemblyLoadContext(isCollectible: false)
    {
        private readonly AssemblyDependencyResolver _resolver = new(main);

        protected override Assembly? Load(AssemblyName name)
            => _resolver.ResolveAssemblyToPath(name) is string path ? LoadFromAssemblyPath(path) : null;
    }
}
