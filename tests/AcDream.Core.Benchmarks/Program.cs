using AcDream.Core.Benchmarks;
using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.Emit;
using Perfolizer.Horology;

// `--accuracy`: the accuracy report (section 3 of docs/accuracy-vs-time.md) and its chart
// (`--chart file.svg`, default accuracy-vs-time.svg; the costs from BenchmarkDotNet's CSV reports in
// `--results folder`, default BenchmarkDotNet.Artifacts/results); anything else goes to
// BenchmarkDotNet (`--filter '*SampleZ*'`, `--list flat`, ...). See README.md in this folder.
if (args.Contains("--accuracy"))
{
    AccuracyReport.Run(Console.Out);
    AccuracyChart.Write(Console.Out, Option("--chart") ?? "accuracy-vs-time.svg", Option("--results") ?? Path.Combine("BenchmarkDotNet.Artifacts", "results"));
    return 0;
}

// `--walk-hash`: the hash of DeterminismWalk's answers, for comparing processes (CI runs it with and
// without DOTNET_EnableHWIntrinsic=0 and compares).
if (args.Contains("--walk-hash"))
{
    DeterminismWalk.Summary walk = DeterminismWalk.Run(ObjectWorld.GfxObjs());
    Console.WriteLine($"{walk.Hash:X16} ({walk.Answers} answers: {walk.Slid} slid, {walk.OnObjects} on object floors, {walk.Refused} refused; casts met something: {walk.CameraHits} camera, {walk.RayHits} ray)");
    return 0;
}

// `--compare`: two rows (of two builds, or of this one) timed side by side in one process, interleaved, repeated in
// independent processes (Compare/SideBySide.cs; README.md, "Ratios that hold").
if (args.Contains("--compare"))
{
    return AcDream.Core.Benchmarks.Compare.SideBySide.Run(args);
}

// `--run ROW [--seconds S] [--base BASE.dll]`: one row (of this build, or of BASE.dll) set up and called in a loop for
// S seconds (default 10), to attach a sampling profiler to (Compare/RunOne.cs; README.md, "Profiles").
if (args.Contains("--run"))
{
    return AcDream.Core.Benchmarks.Compare.RunOne.Run(args);
}

// BenchmarkDotNet's default toolchain builds a child project for the host's runtime (about 15 s per
// run). `--in-process` runs the benchmarks in this (Release) process instead, with no child build.
bool inProcess = args.Contains("--in-process");
args = args.Where(a => a != "--in-process").ToArray();

// A short job: one launch, 12 warm-up and 15 measured iterations of up to 150 ms each, so every
// group runs in about a minute and all of them in a few minutes on two cores. The pilot runs on
// tier-0 code, so the warm-ups must outlast tiered compilation (tier-0 → instrumented → tier-1 with
// PGO): with 3 of them, identical benchmarks differed by 2×. Tier-up starts at once
// (TC_CallCountingDelayMs=0) rather than after 100 ms; the final code is the same.
Job job = Job.Default
    .WithLaunchCount(1)
    .WithWarmupCount(12)
    .WithIterationCount(15)
    .WithIterationTime(TimeInterval.FromMilliseconds(150))
    .WithEnvironmentVariable(new EnvironmentVariable("DOTNET_TC_CallCountingDelayMs", "0"))
    .WithId("Quick");
if (inProcess)
{
    job = job.WithToolchain(InProcessEmitToolchain.Instance);
}

IConfig config = DefaultConfig.Instance
    .AddJob(job)
    .AddColumn(StatisticColumn.Median)
    .WithOptions(ConfigOptions.DisableLogFile);

BenchmarkSwitcher.FromAssembly(typeof(World).Assembly).Run(args, config);
return 0;

string? Option(string name)
{
    int i = Array.IndexOf(args, name);
    return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
}
