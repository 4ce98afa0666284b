using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;
using AcDream.App.Scenes;
using AcDream.App.World;

namespace AcDream.App.Capture;

/// <summary>
/// <c>replay FILE</c>: reads a capture whole (<see cref="CaptureReader"/>), replays it (<see cref="CaptureReplay"/>) and
/// says whether every answer is the same. Exit status 0: all the same; 1: the first call whose answer differs, with the
/// recorded and the replayed answers and the call's inputs; 2: a bad file or option, naming the line and the field.
/// </summary>
internal static partial class ReplayCommand
{
    /// <summary>Exit status when an answer differs.</summary>
    public const int Differs = 1;

    /// <summary>Runs <c>replay</c> with the arguments after it; returns the exit status.</summary>
    public static int Run(string[] args, TextWriter output, TextWriter error)
    {
        if (args.Length != 1 || args[0].StartsWith("--", StringComparison.Ordinal))
        {
            error.WriteLine("error: replay takes one capture file: dotnet run --project src/AcDream.App -- replay FILE. Run with --help for the options.");
            return MainJob.BadInput;
        }

        var clock = Stopwatch.StartNew();
        ReplayDifference? difference;
        int calls, frames;
        CaptureHeader header;
        try
        {
            (header, List<CaptureCall> read) = CaptureReader.ReadFile(args[0]);
            calls = read.Count;
            frames = read.Count(c => c.Kind == CaptureKind.Commit) - 1; // the scene runner commits once before its first frame, then once a frame
            difference = CaptureReplay.Run(header, read);
        }
        catch (CaptureFormatException e)
        {
            error.WriteLine($"error: capture {args[0]}: {e.Message}");
            return MainJob.BadInput;
        }

        output.Write(difference is null
            ? $"replayed {calls} calls: all answers the same ({clock.Elapsed.TotalSeconds.ToString("0.0", CultureInfo.InvariantCulture)} s).{System.Environment.NewLine}"
            : Describe(difference));
        string page = PagePath(args[0]);
        try
        {
            MainJob.WriteAtomically(page, stream => WritePage(header, frames, stream));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"error: cannot write the page {page}: {e.Message}");
            return 1;
        }

        output.WriteLine($"Page: {page}");
        return difference is null ? 0 : Differs;
    }

    /// <summary>
    /// The page of the capture's walk (<see cref="WalkPage"/>): its scene run again for as many frames as the capture
    /// committed, the walk the engine answers now (the one captured when every answer is the same).
    /// </summary>
    internal static void WritePage(CaptureHeader header, int frames, Stream stream)
    {
        Scene scene = header.Scene == CaptureHeader.EmbeddedDefault ? SceneReader.ReadDefault() : SceneReader.ReadFile(header.Scene);
        HoltburgWorld world = scene.CreateWorld();
        WalkPage.Write(SceneRunner.Run(scene, world, Math.Max(1, frames), null, new FrameDrawing()), world, stream);
    }

    /// <summary>Where the replay writes the page: beside the capture, its name without <c>.gz</c> and <c>.jsonl</c>, with <c>.html</c>.</summary>
    internal static string PagePath(string capture)
    {
        string path = Path.GetFullPath(capture);
        foreach (string extension in new[] { ".gz", ".jsonl" })
        {
            path = path.EndsWith(extension, StringComparison.OrdinalIgnoreCase) ? path[..^extension.Length] : path;
        }

        return path + ".html";
    }

    /// <summary>The lines that report a difference: the call's line and kind, both answers (floats as bits, then as numbers) and its inputs.</summary>
    public static string Describe(ReplayDifference d)
    {
        string inputs = CaptureJson.Text(w => CaptureJson.WriteInputs(w, d.Call));
        string nl = System.Environment.NewLine;
        return $"line {d.Line} ({CaptureJson.KindName(d.Call.Kind)}): the replayed answer differs from the recorded one{nl}"
            + $"  recorded: {d.Recorded}{nl}"
            + $"  replayed: {d.Replayed}{nl}"
            + $"  recorded, as numbers: {Numbers(d.Recorded)}{nl}"
            + $"  replayed, as numbers: {Numbers(d.Replayed)}{nl}"
            + $"  inputs: {inputs}{nl}"
            + $"  inputs, as numbers: {Numbers(inputs)}{nl}";
    }

    /// <summary>A line's text with each float's bits (<c>"3F800000"</c>) written as its shortest round-trip number.</summary>
    private static string Numbers(string text) => FloatBits().Replace(text, m =>
        BitConverter.UInt32BitsToSingle(uint.Parse(m.Groups[1].ValueSpan, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture))
            .ToString("R", CultureInfo.InvariantCulture));

    [GeneratedRegex("\"([0-9A-F]{8})\"")]
    private static partial Regex FloatBits();
}
