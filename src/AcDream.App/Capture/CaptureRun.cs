using System.IO.Compression;
using System.Text;
using AcDream.App.Scenes;
using AcDream.App.World;

namespace AcDream.App.Capture;

/// <summary>The main job's run with <c>--capture FILE</c>: the scene run with a <see cref="CaptureRecorder"/> on its engine, written to the file.</summary>
internal static class CaptureRun
{
    /// <summary>
    /// Runs the scene as <see cref="SceneRunner.Run(Scene, HoltburgWorld, int?, AcDream.Core.Physics.IEngineRecorder?, FrameDrawing?)"/> does,
    /// recording every call into <paramref name="path"/> (gzip when its name ends in <c>.gz</c>), written through a temporary
    /// file renamed over it once complete.
    /// </summary>
    /// <returns>The walk, and how many calls the capture holds.</returns>
    /// <exception cref="IOException">The file cannot be written (or <see cref="UnauthorizedAccessException"/>).</exception>
    public static (WalkRecord Record, int Calls) Run(Scene scene, HoltburgWorld world, int? maxFrames, string path, FrameDrawing? drawing = null)
    {
        var header = new CaptureHeader(HeaderScene(scene), world.Center);
        WalkRecord? record = null;
        int calls = 0;
        string? folder = Path.GetDirectoryName(Path.GetFullPath(path));
        Directory.CreateDirectory(folder!);
        MainJob.WriteAtomically(path, stream =>
        {
            using Stream target = path.EndsWith(".gz", StringComparison.OrdinalIgnoreCase) ? new GZipStream(stream, CompressionLevel.SmallestSize, leaveOpen: true) : stream;
            using var writer = new StreamWriter(target, new UTF8Encoding(false), 1 << 16, leaveOpen: true) { NewLine = "\n" };
            var recorder = new CaptureRecorder(writer, header, world);
            record = SceneRunner.Run(scene, world, maxFrames, recorder, drawing);
            calls = recorder.Calls;
        });
        return (record!, calls);
    }

    /// <summary>The header's name of a scene: <see cref="CaptureHeader.EmbeddedDefault"/>, or the file it was read from.</summary>
    public static string HeaderScene(Scene scene) =>
        scene.Source.StartsWith(CaptureHeader.EmbeddedDefault, StringComparison.Ordinal) ? CaptureHeader.EmbeddedDefault : scene.Source;
}
