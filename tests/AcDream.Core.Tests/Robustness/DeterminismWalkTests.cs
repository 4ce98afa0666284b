using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// The walk CI hashes in separate processes, with and without hardware intrinsics (<c>.ci/run</c>): it must
/// exercise what can round differently (slides along objects' walls, object floors, refusals), and give the
/// same hash twice in one process. The engine's sources use no library operation whose rounding depends on
/// the instruction set.
/// </summary>
public class DeterminismWalkTests(ITestOutputHelper output)
{
    [Fact]
    public void The_walk_slides_stands_on_objects_and_hashes_the_same_twice()
    {
        DeterminismWalk.Summary first = DeterminismWalk.Run(RealObjects.GfxObjs, walks: 10);
        DeterminismWalk.Summary second = DeterminismWalk.Run(RealObjects.GfxObjs, walks: 10);
        output.WriteLine($"{first}");
        second.Should().Be(first);
        first.Slid.Should().BeGreaterThan(first.Answers / 10, $"{first}");
        first.OnObjects.Should().BeGreaterThan(first.Answers / 20, $"{first}");
        first.Refused.Should().BeGreaterThan(0, $"{first}");
        first.CameraHits.Should().BeGreaterThan(first.Answers / 40, $"{first}: the camera's casts meet walls and objects");
        first.RayHits.Should().BeGreaterThan(first.Answers / 2, $"{first}: the rays meet the ground ahead");
    }

    /// <summary>Vector Lerp and multiply-add round once where the processor fuses them and twice where it does not.</summary>
    [Fact]
    public void The_engine_uses_no_operation_whose_rounding_depends_on_the_processor()
    {
        string folder = Path.Combine(TestWorldsRoot(), "src", "AcDream.Core");
        string[] fused = ["Lerp(", "FusedMultiplyAdd", "MultiplyAddEstimate", "Math.FusedMultiplyAdd", "CreateFromYawPitchRoll"];
        var found = Directory.GetFiles(folder, "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}"))
            .SelectMany(f => File.ReadAllLines(f).Select((line, i) => (f, i, line)))
            .Where(x => !x.line.TrimStart().StartsWith("//") && fused.Any(x.line.Contains))
            .Select(x => $"{Path.GetFileName(x.f)}:{x.i + 1}: {x.line.Trim()}")
            .ToList();
        found.Should().BeEmpty("their bits differ with and without hardware intrinsics");
    }

    private static string TestWorldsRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "AcDream.sln")))
            {
                return dir.FullName;
            }
        }

        throw new DirectoryNotFoundException("AcDream.sln above " + AppContext.BaseDirectory);
    }
}
