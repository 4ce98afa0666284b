namespace AcDream.App.Tests;

/// <summary>README's "Use" is the quick start's program word for word, so the snippet a new user copies compiles and runs.</summary>
public class ReadmeTests
{
    [Fact]
    public void The_use_section_is_the_quick_start_program_word_for_word()
    {
        string root = AppContext.BaseDirectory;
        while (!File.Exists(Path.Combine(root, "AcDream.sln")))
        {
            root = Path.GetDirectoryName(root) ?? throw new InvalidOperationException($"no AcDream.sln above {AppContext.BaseDirectory}");
        }

        string readme = File.ReadAllText(Path.Combine(root, "README.md")).ReplaceLineEndings("\n");
        string program = File.ReadAllText(Path.Combine(root, "samples", "QuickStart", "Program.cs")).ReplaceLineEndings("\n");
        int use = readme.IndexOf("\n## Use\n", StringComparison.Ordinal);
        use.Should().BeGreaterThan(0, "README has a Use section");
        int start = readme.IndexOf("```csharp\n", use, StringComparison.Ordinal) + "```csharp\n".Length;
        int end = readme.IndexOf("```", start, StringComparison.Ordinal);
        readme[start..end].Should().Be(program, "the Use section's code is samples/QuickStart/Program.cs");
    }
}
