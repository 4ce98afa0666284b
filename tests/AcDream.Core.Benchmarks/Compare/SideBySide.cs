using System.Diagnostics;
using System.Globalization;

namespace AcDream.Core.Benchmarks.Compare;

/// <summary>
/// <c>--compare</c>: speed ratios that hold on a noisy machine. Two benchmark rows (of two builds, or of one) are timed
/// in one process, interleaved in short rounds (A then B, then B then A), so whatever slows the machine for a while
/// slows both sides of every ratio alike. Each process reports the median of the rounds' ratios B/A with a 95 %
/// bootstrap interval of that median; the parent repeats the measurement in independent processes (each compiles and
/// lays out the code anew), every other one loading and setting up B before A (which side is set up first can run
/// several per cent apart, the same build against itself 0.90 one way and 1.13 the other), and reports the median over
/// them and, for each order, the median of its processes with their geometric mean, the balanced figure, which cancels a
/// factor the order puts on one side. With <c>--limit</c>, a pair whose balanced figure (its median, with fewer than 3
/// processes of either order) exceeds it fails the run (the speed gate of <c>.ci/speed-gate</c>, 6 processes).
/// </summary>
/// <remarks>
/// <code>
///   --compare [--base BASE.dll] [--processes P] [--rounds N] [--ms M] [--warmup S] [--limit L] PAIR...
///   PAIR = ROW (with --base: the row in BASE.dll is A, in this build B)  |  ROW_A::ROW_B (two rows of this build)
///   ROW  = Class.Method[@Param=Value,...]     e.g. ResolveOutdoorBenchmarks.Literal@Cells=64,Landblocks=9
/// </code>
/// Each side's benchmark assembly is loaded into a load context of its own with its own AcDream.Core, this build's as
/// well, so both sides run under the same conditions.
/// </remarks>
internal static class SideBySide
{
    private sealed record Options(string? Base, int Processes, int Rounds, double Ms, double Warmup, double? Limit, List<string> Pairs)
    {
        /// <summary>In this (child) process, B is loaded and set up before A (every other process: see <see cref="Parent"/>).</summary>
        public bool BFirst { get; init; }
    }

    public static int Run(string[] args)
    {
        Options o;
        try
        {
            o = Parse(args);
        }
        catch (ArgumentException e)
        {
            Console.Error.WriteLine($"--compare: {e.Message}");
            Console.Error.WriteLine("usage: --compare [--base BASE.dll] [--processes P] [--rounds N] [--ms M] [--warmup S] [--limit L] ROW | ROW_A::ROW_B ...");
            return 2;
        }

        return args.Contains("--child") ? Child(o) : Parent(o, args);
    }

    private static Options Parse(string[] args)
    {
        var o = new Options(null, 4, 40, 10, 2, null, []);
        for (int i = 0; i < args.Length; i++)
        {
            string Next() => i + 1 < args.Length ? args[++i] : throw new ArgumentException($"{args[i]} needs a value");
            double Number() => double.Parse(Next(), CultureInfo.InvariantCulture);
            switch (args[i])
            {
                case "--compare": case "--child": break;
                case "--b-first": o = o with { BFirst = true }; break;
                case "--base": o = o with { Base = Path.GetFullPath(Next()) }; break;
                case "--processes": o = o with { Processes = (int)Number() }; break;
                case "--rounds": o = o with { Rounds = (int)Number() }; break;
                case "--ms": o = o with { Ms = Number() }; break;
                case "--warmup": o = o with { Warmup = Number() }; break;
                case "--limit": o = o with { Limit = Number() }; break;
                default:
                    if (args[i].StartsWith("--", StringComparison.Ordinal))
                    {
                        throw new ArgumentException($"unknown option {args[i]}");
                    }

                    o.Pairs.Add(args[i]);
                    break;
            }
        }

        if (o.Pairs.Count == 0 || o.Processes < 1 || o.Rounds < 3 || o.Ms <= 0)
        {
            throw new ArgumentException("name at least one pair; processes ≥ 1, rounds ≥ 3, ms > 0");
        }

        if (o.Base is null && o.Pairs.Any(p => !p.Contains("::", StringComparison.Ordinal)))
        {
            throw new ArgumentException("without --base each pair is ROW_A::ROW_B");
        }

        return o;
    }

    /// <summary>One process's measurement: one line per pair, <c>ratio lo hi nsA nsB name</c>.</summary>
    private static int Child(Options o)
    {
        string self = typeof(SideBySide).Assembly.Location;
        foreach (string pair in o.Pairs)
        {
            (string a, string b) = o.Base is null ? Split(pair) : (pair, pair);
            Measurement m;
            if (o.BFirst)
            {
                Row rowB = Row.Load(self, b), rowA = Row.Load(o.Base ?? self, a);
                m = Measure(rowB, rowA, o).Inverse();
            }
            else
            {
                Row rowA = Row.Load(o.Base ?? self, a), rowB = Row.Load(self, b);
                m = Measure(rowA, rowB, o);
            }

            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"= {m.Ratio:F4} {m.Low:F4} {m.High:F4} {m.NsA:F1} {m.NsB:F1} {Name(o, pair)}"));
        }

        return 0;
    }

    private static (string A, string B) Split(string pair)
    {
        string[] parts = pair.Split("::");
        return parts.Length == 2 ? (parts[0], parts[1]) : throw new ArgumentException($"'{pair}' is not ROW_A::ROW_B");
    }

    /// <summary>A pair's name in the report: the row (two builds), or "B ÷ A" (two rows).</summary>
    private static string Name(Options o, string pair)
    {
        if (o.Base is not null)
        {
            return pair;
        }

        (string a, string b) = Split(pair);
        return $"{b} ÷ {a}";
    }

    private readonly record struct Measurement(double Ratio, double Low, double High, double NsA, double NsB)
    {
        /// <summary>The same measurement read the other way round (A/B as B/A).</summary>
        public Measurement Inverse() => new(1 / Ratio, 1 / High, 1 / Low, NsB, NsA);
    }

    private static Measurement Measure(Row a, Row b, Options o)
    {
        a.Setup();
        b.Setup();
        var warm = Stopwatch.StartNew();
        while (warm.Elapsed.TotalSeconds < o.Warmup)
        {
            a.Time(1);
            b.Time(1);
        }

        int na = a.Calibrate(o.Ms), nb = b.Calibrate(o.Ms);
        var ratios = new double[o.Rounds];
        var ta = new double[o.Rounds];
        var tb = new double[o.Rounds];
        for (int r = 0; r < o.Rounds; r++)
        {
            if ((r & 1) == 0)
            {
                ta[r] = a.Time(na);
                tb[r] = b.Time(nb);
            }
            else
            {
                tb[r] = b.Time(nb);
                ta[r] = a.Time(na);
            }

            ratios[r] = tb[r] / ta[r];
        }

        (double lo, double hi) = Statistics.MedianInterval(ratios);
        return new Measurement(Statistics.Median(ratios), lo, hi, Statistics.Median(ta), Statistics.Median(tb));
    }

    /// <summary>
    /// Runs the measurement in <see cref="Options.Processes"/> child processes, one after another, and reports each and the
    /// median over them. With a limit, the pairs judged above it (<see cref="Judged"/>) are measured again in as many processes,
    /// and judged over all of theirs: a process's code layout can move one row's ratio by several per cent (the camera's
    /// cast of the same engine read 0.90–1.13), and a real slowdown stays above the limit in both passes.
    /// </summary>
    private static int Parent(Options o, string[] args)
    {
        var byPair = new Dictionary<string, List<double>>();
        var bFirst = new Dictionary<string, List<bool>>();
        var order = new List<string>();
        Console.WriteLine($"{"pair (B ÷ A)",-72} {"B/A",7} {"95 % interval",17} {"A ns",9} {"B ns",9}");
        if (!Measure(o, args, o.Pairs, byPair, bFirst, order))
        {
            return 2;
        }

        List<string> again = o.Limit is double first ? [.. o.Pairs.Where(pair => Judged(byPair[Name(o, pair)], bFirst[Name(o, pair)]) > first)] : [];
        if (again.Count > 0)
        {
            Console.WriteLine($"--- above the limit over {o.Processes} processes, measured again: {string.Join(", ", again)}");
            string[] options = [.. args.Where(a => !o.Pairs.Contains(a))];
            if (!Measure(o, [.. options, .. again], again, byPair, bFirst, order))
            {
                return 2;
            }
        }

        Console.WriteLine($"--- median over the processes (B/A){(o.Limit is double l ? $", limit {l:F2}" : "")}:");
        bool over = false;
        foreach (string name in order)
        {
            List<double> v = byPair[name];
            double median = Statistics.Median([.. v]);
            bool fails = o.Limit is double limit && Judged(v, bFirst[name]) > limit;
            over |= fails;
            string each = string.Join(' ', v.Select(x => x.ToString("F3", CultureInfo.InvariantCulture)));
            Console.WriteLine($"{name,-72} {median.ToString("F3", CultureInfo.InvariantCulture),7}  ({each}){(fails ? "  ABOVE THE LIMIT" : "")}");
            if (Balanced(v, bFirst[name]) is (double aFirst, double bFirstMedian, double balanced))
            {
                Console.WriteLine($"{"",-72} {balanced.ToString("F3", CultureInfo.InvariantCulture),7}  balanced: A set up first {aFirst.ToString("F3", CultureInfo.InvariantCulture)}, B first {bFirstMedian.ToString("F3", CultureInfo.InvariantCulture)}");
            }
        }

        return over ? 1 : 0;
    }

    /// <summary>
    /// The medians of the processes that set A up first and of those that set B up first, and their geometric mean: which
    /// side is set up first can move one row's ratio by ±10 % (the camera's cast of one build against a copy of itself read
    /// 0.90–0.94 one way and 1.05–1.13 the other), the same factor both ways, which the geometric mean cancels. Null
    /// without a process of each order.
    /// </summary>
    private static (double AFirst, double BFirst, double Balanced)? Balanced(List<double> ratios, List<bool> bFirst)
    {
        double[] a = [.. ratios.Where((_, i) => !bFirst[i])], b = [.. ratios.Where((_, i) => bFirst[i])];
        if (a.Length == 0 || b.Length == 0)
        {
            return null;
        }

        double ma = Statistics.Median(a), mb = Statistics.Median(b);
        return (ma, mb, Math.Sqrt(ma * mb));
    }

    /// <summary>
    /// What a limit judges: the balanced figure (<see cref="Balanced"/>) with at least 3 processes of each order, else the
    /// median over them all (with 2 of an order its median is their mean, which one stray process moves: a gate run read
    /// 1.312 in one process of 4, balanced 1.068, median 1.000).
    /// </summary>
    private static double Judged(List<double> ratios, List<bool> bFirst) =>
        bFirst.Count(b => b) >= 3 && bFirst.Count(b => !b) >= 3 && Balanced(ratios, bFirst) is (_, _, double balanced)
            ? balanced
            : Statistics.Median([.. ratios]);

    /// <summary>Measures <paramref name="pairs"/> (named in <paramref name="args"/>) in <see cref="Options.Processes"/> child processes, adding each process's ratio per pair.</summary>
    private static bool Measure(Options o, string[] args, List<string> pairs, Dictionary<string, List<double>> byPair, Dictionary<string, List<bool>> bFirst, List<string> order)
    {
        string self = typeof(SideBySide).Assembly.Location;
        for (int p = 1; p <= o.Processes; p++)
        {
            var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, UseShellExecute = false };
            start.ArgumentList.Add(self);
            foreach (string a in args)
            {
                start.ArgumentList.Add(a);
            }

            start.ArgumentList.Add("--child");
            if (p % 2 == 0)
            {
                start.ArgumentList.Add("--b-first"); // (which side is set up first can run a few per cent apart: alternate)
            }

            using Process child = Process.Start(start) ?? throw new InvalidOperationException("could not start a measuring process");
            string? line;
            while ((line = child.StandardOutput.ReadLine()) is not null)
            {
                if (!line.StartsWith("= ", StringComparison.Ordinal))
                {
                    if (!line.StartsWith("//", StringComparison.Ordinal))
                    {
                        Console.WriteLine(line); // (the setups' own notes start with "//")
                    }

                    continue;
                }

                string[] f = line[2..].Split(' ', 6);
                string name = f[5];
                if (!byPair.TryGetValue(name, out List<double>? list))
                {
                    byPair[name] = list = [];
                    bFirst[name] = [];
                    order.Add(name);
                }

                list.Add(double.Parse(f[0], CultureInfo.InvariantCulture));
                bFirst[name].Add(p % 2 == 0);
                Console.WriteLine($"{name,-72} {f[0],7} {$"[{f[1]}, {f[2]}]",17} {f[3],9} {f[4],9}   (process {p})");
            }

            child.WaitForExit();
            if (child.ExitCode != 0)
            {
                Console.WriteLine($"the measuring process {p} failed (exit {child.ExitCode}) on {pairs.Count} pair(s)");
                return false;
            }
        }

        return true;
    }
}
