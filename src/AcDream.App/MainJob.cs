using System.Globalization;
using System.Text;
using System.Xml;
using System.Xml.Linq;
using AcDream.App.Capture;
using AcDream.App.Scenes;
using AcDream.App.World;

namespace AcDream.App;

/// <summary>
/// The main job: runs a scene (the embedded Holtburg walk by default), prints the summary and writes
/// the SVG and the page beside it (<see cref="WalkPage"/>), and with <c>--capture</c> the engine's calls (<c>replay FILE</c>
/// replays them). Exit status 0 on success, 2 on a bad option or scene file, 1 when the SVG, the page or the capture
/// cannot be written. The SVG and the page are each written to a temporary file and renamed over the old one, so a
/// failure never leaves a damaged file.
/// </summary>
internal static class MainJob
{
    /// <summary>Exit status for bad input (options or scene file).</summary>
    public const int BadInput = 2;

    /// <summary>Usage text for <c>--help</c>.</summary>
    public const string Usage = """
        Usage: dotnet run --project src/AcDream.App -- [options]
               dotnet run --project src/AcDream.App -- replay FILE

        Runs a scripted walk through the physics engine, headless, and prints what happened:
        the cells visited, moves slid along walls and refused, where a chase camera's boom
        was pulled in, what the scene's pointer rays met, airborne frames, landblocks
        streamed, the end point.
        Writes an SVG (top-down map and Z profile) to the output folder, and beside it a
        page (.html, opens from disk) that scrubs the walk in 3-D.

        Options:
          --scene FILE   run this scene file (JSON, see docs/scenes.md) instead of the
                         embedded Holtburg walk
          --out DIR      folder for the SVG and the page (default: out)
          --frames N     stop after N frames (30 frames = 1 s)
          --capture FILE also record every call of the engine and its answer into
                         FILE (JSON Lines, see docs/capture.md; gzip if FILE ends in .gz)
          --quiet        print only the SVG path
          --help         print this text

        Exit status: 0 done, 1 the SVG, the page or the capture could not be written, 2 a bad
        option or scene file.

        replay FILE      replays a capture against a fresh engine in the scene's world and
                         compares every answer bit for bit: exit status 0 all the same,
                         1 the first line whose answer differs (both answers and the call's
                         inputs printed), 2 a bad file (its line and field named);
                         it writes the walk's page beside FILE (FILE.html) and says where.
        """;

    /// <summary>Runs the job with command-line <paramref name="args"/>; returns the exit status.</summary>
    public static int Run(string[] args, TextWriter output, TextWriter error)
    {
        if (args is ["replay", .. var rest])
        {
            return ReplayCommand.Run(rest, output, error);
        }

        string? scenePath = null, outDir = null, capturePath = null;
        int? frames = null;
        bool quiet = false;
        for (int i = 0; i < args.Length; i++)
        {
            string arg = args[i];
            switch (arg)
            {
                case "--help" or "-h":
                    output.Write(Usage);
                    output.WriteLine();
                    return 0;
                case "--quiet":
                    quiet = true;
                    break;
                case "--scene" or "--out" or "--frames" or "--capture":
                    if (i + 1 >= args.Length || args[i + 1].StartsWith("--", StringComparison.Ordinal))
                    {
                        return Fail(error, $"option {arg} needs a value ({(arg == "--frames" ? "a number of frames" : arg == "--out" ? "a folder" : arg == "--capture" ? "a capture file" : "a scene file")}).");
                    }

                    string value = args[++i];
                    if (arg == "--scene")
                    {
                        scenePath = value;
                    }
                    else if (arg == "--out")
                    {
                        outDir = value;
                    }
                    else if (arg == "--capture")
                    {
                        capturePath = value;
                    }
                    else if (int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n > 0)
                    {
                        frames = n;
                    }
                    else
                    {
                        return Fail(error, $"option --frames: \"{value}\" is not a whole number of frames > 0.");
                    }

                    break;
                default:
                    return Fail(error, $"unknown option \"{arg}\".");
            }
        }

        Scene scene;
        try
        {
            scene = scenePath is null ? SceneReader.ReadDefault() : SceneReader.ReadFile(scenePath);
        }
        catch (SceneFormatException e)
        {
            error.WriteLine($"error: scene {e.Message}");
            return BadInput;
        }

        HoltburgWorld world = scene.CreateWorld();
        WalkRecord record;
        int calls = 0;
        try
        {
            (record, calls) = capturePath is null ? (SceneRunner.Run(scene, world, frames, null, new FrameDrawing()), 0) : CaptureRun.Run(scene, world, frames, capturePath, new FrameDrawing());
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"error: cannot write the capture {capturePath}: {e.Message}");
            return 1;
        }

        string svgPath = Path.GetFullPath(Path.Combine(outDir ?? "out", FileName(scene.Name) + ".svg"));
        string pagePath = Path.ChangeExtension(svgPath, ".html");
        XDocument svg = WalkSvg.Build(record, world);
        try
        {
            Directory.CreateDirectory(Path.GetDirectoryName(svgPath)!);
            WriteAtomically(svgPath, stream =>
            {
                using var writer = XmlWriter.Create(stream, new XmlWriterSettings { Encoding = new UTF8Encoding(false), Indent = true });
                svg.Save(writer);
            });
            WriteAtomically(pagePath, stream => WalkPage.Write(record, world, stream));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"error: cannot write the SVG {svgPath} or the page {pagePath}: {e.Message}");
            return 1;
        }

        output.Write(quiet ? $"SVG: {svgPath}{System.Environment.NewLine}" : WalkReport.Format(record, svgPath) + $"Page: {pagePath}{System.Environment.NewLine}");
        if (capturePath is not null)
        {
            output.WriteLine($"Capture: {Path.GetFullPath(capturePath)} ({calls} calls)");
        }
        return 0;
    }

    /// <summary>
    /// Writes a file through a temporary file in the same folder, renamed over <paramref name="path"/>
    /// only once it is complete: a failure leaves an earlier file of that name as it was, and removes
    /// the temporary file.
    /// </summary>
    internal static void WriteAtomically(string path, Action<Stream> write)
    {
        string temporary = Path.Combine(Path.GetDirectoryName(Path.GetFullPath(path))!, $".{Path.GetFileName(path)}.{Guid.NewGuid():N}.tmp");
        try
        {
            using (var stream = new FileStream(temporary, FileMode.CreateNew, FileAccess.Write))
            {
                write(stream);
            }

            File.Move(temporary, path, overwrite: true);
        }
        finally
        {
            File.Delete(temporary); // nothing to delete once moved
        }
    }

    private static int Fail(TextWriter error, string message)
    {
        error.WriteLine($"error: {message} Run with --help for the options.");
        return BadInput;
    }

    /// <summary>A file name from a scene name: letters and digits kept, the rest '-'.</summary>
    private static string FileName(string name)
    {
        var text = new StringBuilder();
        foreach (char c in name.ToLowerInvariant())
        {
            text.Append(char.IsAsciiLetterOrDigit(c) ? c : '-');
        }

        return text.ToString().Trim('-') is { Length: > 0 } file ? file : "scene";
    }
}
