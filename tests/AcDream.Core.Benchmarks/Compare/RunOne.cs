using System.Diagnostics;
using System.Globalization;

namespace AcDream.Core.Benchmarks.Compare;

/// <summary>
/// <c>--run ROW [--seconds S] [--base BASE.dll]</c>: one benchmark row of this build (or of the benchmark assembly
/// BASE.dll of another build, in its own load context as with <c>--compare</c>), set up and then called in a loop for S
/// seconds (default 10), so a sampling profiler can be attached to exactly that row (README.md, "Profiles"). Prints
/// the process id once set up and the mean time per operation at the end.
/// </summary>
internal static class RunOne
{
    public static int Run(string[] args)
    {
        string? spec = null;
        string dll = typeof(World).Assembly.Location;
        double seconds = 10;
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--run" when i + 1 < args.Length: spec = args[++i]; break;
                case "--base" when i + 1 < args.Length: dll = Path.GetFullPath(args[++i]); break;
                case "--seconds" when i + 1 < args.Length: seconds = double.TryParse(args[++i], CultureInfo.InvariantCulture, out double s) ? s : double.NaN; break;
                default: break;
            }
        }

        if (spec is null || !(seconds > 0))
        {
            Console.Error.WriteLine("usage: --run Class.Method[@Param=Value,...] [--seconds S] [--base BASE.dll]   (S > 0, default 10)");
            return 2;
        }

        Row row;
        try
        {
            row = Row.Load(dll, spec);
        }
        catch (ArgumentException e)
        {
            Console.Error.WriteLine($"--run: {e.Message}");
            return 2;
        }

        row.Setup();
        Console.WriteLine($"pid {Environment.ProcessId}: running {spec} for {seconds.ToString(CultureInfo.InvariantCulture)} s");
        int batch = row.Calibrate(50);
        long invocations = 0;
        double totalNs = 0;
        var clock = Stopwatch.StartNew();
        while (clock.Elapsed.TotalSeconds < seconds)
        {
            totalNs += row.Time(batch) * batch;
            invocations += batch;
        }

        Console.WriteLine($"{spec}: {totalNs / invocations:F1} ns/op over {invocations} invocations");
        return 0;
    }
}
